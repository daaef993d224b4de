// The class page (grader/trusted/class_page.hpp) from results.json texts made here: a mistake
// counts students, not tests; every text is escaped, in the elements and in the JSON block; the
// csv neutralises a formula; the anonymous page names nobody. tests/deploy/class_page.sh checks
// the same on a real regrade, where a name cannot hold a "/" (a folder's name).
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "class_page.hpp"

namespace grading = opspace::grading;
using Json = nlohmann::json;

namespace {

const std::string kHostile = "</script><script>alert(1)</script><img src=x onerror=alert(2)>";

// A results.json as hw2-grade writes it: two failed tests of 1b both naming `mistake`, one
// simulated test's run of three points.
std::string results(const std::string& mistake) {
  Json run{{"statistic", "tip error " + kHostile}, {"quantity", "q"}, {"unit", "mm"}, {"unit_scale", 1000},
           {"bound", 0.005}, {"upper", true}, {"judged", "j"}, {"judged_from", 0.0}, {"yours", 0.7},
           {"reference", 0.001}, {"t", "0 1 2"}, {"v", "0.1 0.5 0.7"}, {"reference_t", "0 1 2"}, {"reference_v", "0.001 0.001 0.001"}};
  Json tests = Json::array();
  for (const char* name : {"iv. the law", "iv. in simulation the run"})
    tests.push_back(Json{{"name", std::string("1b ") + name}, {"score", 0}, {"max_score", 4}, {"status", "failed"},
                         {"extra_data", {{"problem", "1b"}, {"test", name}, {"mistake", mistake}, {"interrupted", false},
                                         {"grader_fault", false}, {"runs", Json::array({run})}}}});
  return Json{{"score", 0}, {"max_score", 8}, {"extra_data", {{"grader", {{"seed", 1}, {"grader_faults", 0}}}}}, {"tests", tests}}.dump();
}

std::string page(const std::vector<grading::ClassStudent>& students, bool anonymous) {
  std::ostringstream out;
  grading::write_class_page(out, students, {anonymous});
  return out.str();
}

Json data_of(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"class-data\">";
  const std::size_t at = html.find(open) + open.size();
  return Json::parse(html.substr(at, html.find("</script>", at) - at));
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
