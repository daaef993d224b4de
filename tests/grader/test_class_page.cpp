// The class page (grader/trusted/class/class_page.hpp) from results.json texts made here: a mistake
// counts students, not tests; every text is escaped, in the elements and in the JSON block; the
// csv neutralises a formula; the anonymous page names nobody; a number it cannot draw costs its
// own row, in bounded time and memory, and so do the plots of report_html.hpp.
// tests/deploy/class_page.sh checks the same on a real regrade, where a name cannot hold a "/" (a
// folder's name); tests/deploy/class_page_refusals.sh hw2-class on hostile and missing folders.
#include <doctest/doctest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "class/class_page.hpp"
#include "report/plot_png.hpp"
#include "report/report_html.hpp"

namespace grading = opspace::grading;
using Json = nlohmann::json;

namespace {

const std::string kHostile = "</script><script>alert(1)</script><img src=x onerror=alert(2)>";

// A results.json as hw2-grade writes it: two failed tests of 1b both naming `mistake`, one
// simulated test's run of three points (times `t`, values `v` in m, shown in mm).
std::string results(const std::string& mistake, const std::string& t = "0 1 2", const std::string& v = "0.1 0.5 0.7") {
  Json run{{"statistic", "tip error " + kHostile}, {"quantity", "q"}, {"unit", "mm"}, {"unit_scale", 1000},
           {"bound", 0.005}, {"upper", true}, {"judged", "j"}, {"judged_from", 0.0}, {"yours", 0.7},
           {"reference", 0.001}, {"t", t}, {"v", v}, {"reference_t", "0 1 2"}, {"reference_v", "0.001 0.001 0.001"}};
  Json tests = Json::array();
  for (const char* name : {"iv. the law", "iv. in simulation the run"})
    tests.push_back(Json{{"name", std::string("1b ") + name}, {"score", 0}, {"max_score", 4}, {"status", "failed"},
                         {"extra_data", {{"problem", "1b"}, {"test", name}, {"mistake", mistake}, {"interrupted", false},
                                         {"grader_fault", false}, {"runs", Json::array({run})}}}});
  return Json{{"score", 0}, {"max_score", 8}, {"extra_data", {{"grader", {{"seed", 1}, {"grader_faults", 0}}}}}, {"tests", tests}}.dump();
}

std::string page(const std::vector<grading::ClassStudent>& students, bool anonymous) {
  std::ostringstream out;
  grading::write_class_page(out, students, {anonymous, ""});
  return out.str();
}

Json data_of(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"class-data\">";
  const std::size_t at = html.find(open) + open.size();
  return Json::parse(html.substr(at, html.find("</script>", at) - at));
}

// The text `make` returns, made in a child process given 20 s (a page of a few students takes
// milliseconds; the rest is room for a sanitized build on a busy machine) and, but under
// AddressSanitizer (whose shadow memory alone is terabytes of address space), 1 GiB of address
// space (this test's process holds about 100 MB): the tick loop of issue 59 grew past 4 GiB in
// seconds. "" when the child failed, ran out of memory or was killed at 20 s.
std::string bounded(const std::function<std::string()>& make) {
  char path[] = "/tmp/opspace-class-page-XXXXXX";
  const int fd = mkstemp(path);
  REQUIRE(fd >= 0);
  close(fd);
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
#if !defined(__SANITIZE_ADDRESS__)
    const rlimit memory{1L << 30, 1L << 30};
    setrlimit(RLIMIT_AS, &memory);
#endif
    alarm(20);
    try {
      std::ofstream(path, std::ios::binary) << make();
    } catch (...) {
      _exit(1);
    }
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  std::remove(path);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    MESSAGE("the child " << (WIFSIGNALED(status) ? "was killed by signal " + std::to_string(WTERMSIG(status)) : "failed"));
    return "";
  }
  return text.str();
}

// The part of `html` from `open` to the next `close`, both included ("" if none).
std::string part(const std::string& html, const std::string& open, const std::string& close) {
  const std::size_t at = html.find(open);
  if (at == std::string::npos) return "";
  const std::size_t end = html.find(close, at);
  return end == std::string::npos ? "" : html.substr(at, end + close.size() - at);
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

}  // namespace

TEST_CASE("a mistake counts each student once, whatever the tests it cost") {
  // Two students, each with the mistake named on two tests: 2 students, not 4 tests.
  const std::vector<grading::ClassStudent> students{grading::read_student("ann", results("the slip")),
                                                     grading::read_student("bob", results("the slip"))};
  const Json data = data_of(page(students, false));
  REQUIRE(data["mistakes"].size() == 1);
  CHECK(data["mistakes"][0]["students"] == Json::array({1, 2}));
  CHECK(data["mistakes"][0]["tests"]["1b iv. the law"] == 2);
  std::ostringstream csv;
  grading::write_mistakes_csv(csv, students, {});
  CHECK(csv.str() == "rank,problem,mistake,students,tests,who\n1,\"1b\",\"the slip\",2,"
                     "\"1b iv. in simulation the run (2); 1b iv. the law (2)\",\"ann; bob\"\n");
}

TEST_CASE("every text on the class page is escaped, the JSON block's too, and the csv's formulas neutralised") {
  const std::vector<grading::ClassStudent> students{grading::read_student(kHostile, results(kHostile)),
                                                     grading::read_student("=cmd|' -C calc'!A0", results(kHostile))};
  const std::string html = page(students, false);
  // The page's own elements are its only tags: no text of theirs opens one.
  CHECK(html.find("<script>alert") == std::string::npos);
  CHECK(html.find("<img src=x") == std::string::npos);
  CHECK(html.find("&lt;img src=x onerror=alert(2)&gt;") != std::string::npos);
  // The JSON block reads back the texts as they were, and only its own </script> closes it.
  const Json data = data_of(html);
  CHECK(data["students"][0]["name"] == kHostile);
  CHECK(data["mistakes"][0]["mistake"] == kHostile);
  // A name that a spreadsheet reads as a formula (OWASP's example), alone in its field.
  const std::vector<grading::ClassStudent> formula{grading::read_student("=cmd|' -C calc'!A0", results("m"))};
  std::ostringstream alone;
  grading::write_mistakes_csv(alone, formula, {});
  CHECK(alone.str().find(",\"'=cmd|' -C calc'!A0\"\n") != std::string::npos);
}

TEST_CASE("the anonymous class page numbers the students and names none") {
  const std::vector<grading::ClassStudent> students{grading::read_student("zelda-q", results("the slip"))};
  const std::string html = page(students, true);
  CHECK(html.find("zelda") == std::string::npos);
  CHECK(html.find(">student 1<") != std::string::npos);
  CHECK(data_of(html)["students"][0].count("name") == 0);
}

TEST_CASE("a results.json with numbers the page cannot draw costs its own row, in bounded time and memory") {
  const std::vector<grading::ClassStudent> honest{grading::read_student("ann", results("the slip")),
                                                   grading::read_student("bob", results("the other slip", "0 1 2", "0.2 0.3 0.4"))};
  // The hostile students name bob's mistake: ranked first in both classes, it keeps its colour.
  std::vector<grading::ClassStudent> students = honest;
  // Issue 59's file: 1e306 m is 1e309 mm, infinite once scaled, and hung the page's tick loop.
  students.push_back(grading::read_student("huge", results("the other slip", "0 1 2", "0.1 1e306 0.7")));
  // Infinite as written (strtod reads "inf" and "1e400" as infinity).
  students.push_back(grading::read_student("infinite", results("the other slip", "0 1 inf", "0.1 1e400 0.7")));
  // A time that is not a number: the plot cannot place the run.
  students.push_back(grading::read_student("nan", results("the other slip", "0 nan 2", "nan nan nan")));
  // Finite but absurd: 1e200 m, far beyond any quantity of the problems; and a score of 1e300.
  std::string absurd = results("the other slip", "0 1 2", "0.1 1e200 0.7");
  absurd.replace(absurd.find("\"score\":0,"), 10, "\"score\":1e300,");
  students.push_back(grading::read_student("absurd", absurd));
  const std::string html = bounded([&] { return page(students, false); });
  REQUIRE(!html.empty());
  // The honest students' plots as if the class were theirs alone: no refused run shares a scale.
  const std::string alone = page(honest, false);
  CHECK(part(html, "<section id=\"runs\">", "</section>") == part(alone, "<section id=\"runs\">", "</section>"));
  const Json data = data_of(html);
  REQUIRE(data["students"].size() == 6);
  CHECK(data["students"][0]["score"] == 0);
  CHECK(data["students"][5]["score"] == 0);  // 1e300 refused, counted 0
  // Each hostile row, and only those, is noted among the gradings to look at, saying what was refused.
  REQUIRE(data["attention"].size() == 4);
  for (std::size_t k = 0; k < 4; ++k) {
    CHECK(data["attention"][k]["student"] == k + 3);
    CHECK(data["attention"][k]["why"].dump().find("refused") != std::string::npos);
  }
  CHECK(data["attention"][3]["why"].dump().find("score") != std::string::npos);
  // The mistakes still count every student who made one: a refused number is not a refused grade.
  CHECK(data["mistakes"][0]["students"] == Json::array({2, 3, 4, 5, 6}));
}

TEST_CASE("the plots' every loop is bounded, whatever the values: a figure of infinite and absurd numbers") {
  // Issue 59's series: 1e306 m shown in mm, infinite; times to infinity; a bound of the smallest
  // double, a thousandth of which is 0 (the log axis's start); a judged start at infinity.
  opspace::grading::RunFigure f;
  f.quantity = "q", f.unit = "mm", f.unit_scale = 1000, f.bound = 5e-324, f.judged_from = HUGE_VAL;
  f.student = {{0, 1, HUGE_VAL}, {0.1, 1e306, 0.7}};
  f.reference = {{0, 1, 2}, {0.001, 0.001, 0.001}};
  const std::string svg = bounded([&] { return grading::svg_plot(f); });
  REQUIRE(!svg.empty());
  // The time axis's labels, the value axis's and its name: at most 12 labels on each axis
  // (report_html.cpp's kMaxTicks) and one name apiece.
  CHECK(count(svg, "<text") <= 2 * 12 + 2);
  CHECK(svg.find("nan") == std::string::npos);
  CHECK(svg.find("inf") == std::string::npos);
  const std::string small = bounded([&] { return grading::svg_small_multiple(f, {{f.student, "#000", 1}}, 300, 150); });
  REQUIRE(!small.empty());
  CHECK(count(small, "<text") <= 2 * 12 + 2);
  CHECK(!bounded([&] { return grading::png_plot(f); }).empty());
  // A linear axis from -1e306 to 1e306 (its span infinite), and a time axis of 1e-320 s.
  f.bound = NAN, f.judged_from = 0, f.student = {{0, 1e-320}, {-1e306, 1e306}}, f.reference = {};
  const std::string wide = bounded([&] { return grading::svg_plot(f); });
  REQUIRE(!wide.empty());
  CHECK(count(wide, "<text") <= 2 * 12 + 2);
  CHECK(!bounded([&] { return grading::png_plot(f); }).empty());
}
