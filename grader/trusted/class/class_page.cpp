#include "class/class_page.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>
#include <ostream>
#include <set>

#include "class/class_mistakes.hpp"
#include "report/report_html.hpp"
#include "common/student_text.hpp"

namespace opspace::grading {

namespace {

using Json = nlohmann::ordered_json;

// A named mistake's curves; blue and green are the reference's and the bound's.
constexpr const char* kPalette[] = {"#d62728", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#bcbd22", "#17becf", "#7f3f00"};
constexpr const char* kPassed = "#aaaaaa";
constexpr const char* kUnnamed = "#222222";
constexpr double kPanelWidth = 300, kPanelHeight = 150;

std::string points(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

// What the page calls student i: their folder's name, escaped where shown (a name is the
// student's text), or "student i+1".
std::string name_of(const std::vector<ClassStudent>& s, std::size_t i, const ClassPageOptions& o) {
  return o.anonymous ? "student " + std::to_string(i + 1) : escape_student_text(s[i].name, false, false);
}

// A path's bytes percent-encoded but for letters, digits, - . _ ~ and /: no name can end the
// attribute or read as another URL.
std::string url_path(const std::string& path) {
  std::string out;
  for (const unsigned char c : path) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      out += static_cast<char>(c);
    } else {
      char b[4];
      std::snprintf(b, sizeof b, "%%%02X", c);
      out += b;
    }
  }
  return out;
}

std::string student_html(const std::vector<ClassStudent>& s, std::size_t i, const ClassPageOptions& o) {
  const std::string shown = html_text(name_of(s, i, o));
  if (o.anonymous || s[i].report.empty()) return "<span class=\"student\">" + shown + "</span>";
  return "<a class=\"student\" href=\"" + html_text(url_path(s[i].report)) + "\">" + shown + "</a>";
}

// Every test of the class, in the order first seen.
std::vector<std::string> test_order(const std::vector<ClassStudent>& students) {
  std::vector<std::string> order;
  std::set<std::string> seen;
  for (const ClassStudent& s : students)
    for (const ClassTest& t : s.tests)
      if (seen.insert(test_key(t)).second) order.push_back(test_key(t));
  return order;
}

std::string colour_of(const std::vector<MistakeRow>& ranked, const std::string& problem, const std::string& mistake) {
  for (std::size_t k = 0; k < ranked.size(); ++k)
    if (ranked[k].problem == problem && ranked[k].mistake == mistake) return kPalette[k % std::size(kPalette)];
  return kUnnamed;
}

// Why student s needs a look before their grade is read; empty when nothing does.
std::vector<std::string> attention(const ClassStudent& s) {
  std::vector<std::string> why;
  if (!s.not_graded.empty()) why.push_back("not graded: " + s.not_graded);
  if (s.grader_faults > 0) why.push_back(std::to_string(s.grader_faults) + " test(s) or problem(s) lost to the grader's own faults");
  if (s.unprotected) why.push_back("UNPROTECTED: graded without the whole sandbox");
  const auto joined = [](const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
  };
  // A missing file matters where its problem was graded (a regrade of one problem, --problem,
  // leaves the others' stubs ungraded).
  std::vector<std::string> missing;
  for (const std::string& file : s.missing) {
    const std::string key = file.size() > 5 ? file.substr(1, file.size() - 5) : file;
    if (s.tests.empty() || std::any_of(s.tests.begin(), s.tests.end(), [&](const ClassTest& t) { return t.problem == key; }))
      missing.push_back(file);
  }
  if (!missing.empty()) why.push_back("missing, graded as the stub: " + joined(missing));
  if (!s.misnamed.empty()) why.push_back("misnamed, not graded: " + joined(s.misnamed));
  // A file that did not compile interrupts every test of its problem: said once, by problem.
  std::vector<std::string> not_built;
  for (const ClassTest& t : s.tests)
    if (t.not_built && std::find(not_built.begin(), not_built.end(), t.problem) == not_built.end()) not_built.push_back(t.problem);
  if (!not_built.empty()) why.push_back("did not compile: problem " + joined(not_built));
  const auto interrupted = std::count_if(s.tests.begin(), s.tests.end(), [](const ClassTest& t) { return t.interrupted && !t.not_built; });
  if (interrupted > 0) why.push_back(std::to_string(interrupted) + " test(s) interrupted: the code crashed, timed out or exited");
  // Numbers of its results.json the page cannot draw (class_results.hpp): the file was not the
  // grader's as written, or the grader wrote what it should not have.
  for (const std::string& refused : s.refused) why.push_back("results.json: " + refused);
  why.insert(why.end(), s.notes.begin(), s.notes.end());
  return why;
}

Json ids(const std::vector<std::size_t>& students) {
  Json out = Json::array();
  for (const std::size_t i : students) out.push_back(i + 1);
  return out;
}

void attention_section(std::ostream& out, const std::vector<ClassStudent>& students, const ClassPageOptions& o, Json& data) {
  out << "<section id=\"attention\">\n<h2>Look at these gradings first</h2>\n";
  Json rows = Json::array();
  std::string table;
  for (std::size_t i = 0; i < students.size(); ++i) {
    const std::vector<std::string> why = attention(students[i]);
    if (why.empty()) continue;
    table += "<tr class=\"attention\" data-student=\"" + std::to_string(i + 1) + "\"><td>" + student_html(students, i, o) + "</td><td>";
    for (const std::string& w : why) table += html_text(w) + "<br>";
    table += "</td></tr>\n";
    rows.push_back(Json{{"student", i + 1}, {"why", why}});
  }
  if (table.empty())
    out << "<p>None: every student's files were there, named as asked, compiled and ran whole, in the sandbox, "
           "by a grader that did not fault.</p>\n";
  else out << "<table>\n<tr><th>student</th><th>why</th></tr>\n" << table << "</table>\n";
  out << "</section>\n";
  data["attention"] = std::move(rows);
}

void mistakes_section(std::ostream& out, const std::vector<ClassStudent>& students, const std::vector<MistakeRow>& ranked,
                      const ClassPageOptions& o, Json& data) {
  out << "<section id=\"mistakes\">\n<h2>Known mistakes, the most made first</h2>\n";
  Json rows = Json::array();
  if (ranked.empty()) out << "<p>The grader named no known mistake in this class.</p>\n";
  else out << "<table>\n<tr><th></th><th>problem</th><th>mistake</th><th>students</th><th>tests it cost (students)</th><th>who</th></tr>\n";
  for (std::size_t k = 0; k < ranked.size(); ++k) {
    const MistakeRow& m = ranked[k];
    out << "<tr class=\"mistake\" data-problem=\"" << html_text(m.problem) << "\" data-mistake=\"" << html_text(m.mistake)
        << "\" data-count=\"" << m.students.size() << "\"><td><span class=\"swatch\" style=\"background:"
        << kPalette[k % std::size(kPalette)] << "\"></span></td><td>" << html_text(m.problem) << "</td><td>"
        << html_text(m.mistake) << "</td><td>" << m.students.size() << "</td><td>";
    Json tests = Json::object();
    for (const auto& [test, count] : m.tests) {
      out << html_text(test) << " (" << count << ")<br>";
      tests[test] = count;
    }
    out << "</td><td>";
    for (std::size_t n = 0; n < m.students.size(); ++n) out << (n ? ", " : "") << student_html(students, m.students[n], o);
    out << "</td></tr>\n";
    rows.push_back(Json{{"problem", m.problem}, {"mistake", m.mistake}, {"students", ids(m.students)}, {"tests", tests}});
  }
  if (!ranked.empty()) out << "</table>\n";
  out << "</section>\n";
  data["mistakes"] = std::move(rows);
}

// Per problem: how many students scored each score, and each test's pass rate.
void problems_section(std::ostream& out, const std::vector<ClassStudent>& students, Json& data) {
  out << "<section id=\"problems\">\n<h2>Scores and pass rates per problem</h2>\n";
  std::vector<std::string> keys;
  for (const std::string& test : test_order(students)) {
    const std::string key = test.substr(0, test.find(' '));
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  }
  Json problems = Json::array();
  for (const std::string& key : keys) {
    std::map<double, int> scores;
    std::map<std::string, std::pair<int, int>> rates;  // test: passed, graded
    double max_score = 0.0;
    for (const ClassStudent& s : students) {
      double score = 0.0, most = 0.0;
      bool graded = false;
      for (const ClassTest& t : s.tests) {
        if (t.problem != key) continue;
        graded = true, score += t.score, most += t.max_score;
        auto& [passed, count] = rates[test_key(t)];
        passed += t.passed() ? 1 : 0, ++count;
      }
      if (graded) ++scores[score], max_score = std::max(max_score, most);
    }
    int largest = 1;
    for (const auto& [score, count] : scores) largest = std::max(largest, count);
    out << "<div class=\"problem\" data-problem=\"" << html_text(key) << "\">\n<h3>Problem " << html_text(key) << " (of "
        << points(max_score) << " points)</h3>\n<table class=\"scores\">\n<tr><th>score</th><th>students</th></tr>\n";
    Json histogram = Json::object();
    for (auto it = scores.rbegin(); it != scores.rend(); ++it) {
      out << "<tr data-score=\"" << points(it->first) << "\" data-count=\"" << it->second << "\"><td>" << points(it->first)
          << "</td><td><span class=\"bar\" style=\"width:" << 200 * it->second / largest << "px\"></span> " << it->second
          << "</td></tr>\n";
      histogram[points(it->first)] = it->second;
    }
    out << "</table>\n<table class=\"rates\">\n<tr><th>test</th><th>passed</th></tr>\n";
    Json tests = Json::array();
    for (const std::string& test : test_order(students)) {
      if (!rates.count(test)) continue;
      const auto [passed, graded] = rates[test];
      out << "<tr class=\"rate\" data-test=\"" << html_text(test) << "\" data-passed=\"" << passed << "\" data-graded=\""
          << graded << "\"><td>" << html_text(test) << "</td><td><span class=\"bar\" style=\"width:"
          << 100 * passed / std::max(graded, 1) << "px\"></span> " << passed << " / " << graded << "</td></tr>\n";
      tests.push_back(Json{{"test", test}, {"passed", passed}, {"graded", graded}});
    }
    out << "</table>\n</div>\n";
    problems.push_back(Json{{"problem", key}, {"scores", histogram}, {"tests", tests}});
  }
  out << "</section>\n";
  data["problems"] = std::move(problems);
}

// One student's run of a test's judged statistic, and the group whose colour it takes.
struct Entry {
  std::size_t student;
  const ClassRun* run;
  std::string group;  // the named mistake, or "" (passed / failed with no mistake named)
  bool passed;
};

// The small multiples of one judged run: one plot per group, all on the y scale of the whole.
void run_figure(std::ostream& out, const std::string& test, const std::string& statistic, const std::vector<Entry>& entries,
                const std::vector<MistakeRow>& ranked, Json& data) {
  RunFigure frame;
  const ClassRun& first = *entries.front().run;
  frame.quantity = first.quantity, frame.unit = first.unit, frame.unit_scale = first.unit_scale, frame.bound = first.bound;
  frame.upper = first.upper, frame.judged_from = first.judged_from;
  double t_end = 0.0;
  for (const Entry& e : entries) {
    if (frame.reference.t.empty()) frame.reference = e.run->reference_series;
    // The values every plot must hold (svg_small_multiple): all runs'.
    frame.student.v.insert(frame.student.v.end(), e.run->student.v.begin(), e.run->student.v.end());
    if (!e.run->student.t.empty()) t_end = std::max(t_end, e.run->student.t.back());
  }
  frame.student.t = {t_end};
  // The groups: each named mistake in rank order, then failed with none named, then passed.
  std::vector<std::pair<std::string, std::string>> groups;  // label, colour
  for (const MistakeRow& m : ranked) groups.emplace_back(m.mistake, colour_of(ranked, m.problem, m.mistake));
  groups.emplace_back("failed, no known mistake named", kUnnamed);
  groups.emplace_back("passed", kPassed);
  out << "<figure class=\"class-run\" data-test=\"" << html_text(test) << "\" data-statistic=\"" << html_text(statistic)
      << "\" data-bound=\"" << (std::isfinite(first.bound) ? 1 : 0) << "\">\n<h3>" << html_text(test) << "</h3>\n<p>" << html_text(statistic);
  if (std::isfinite(first.bound))
    out << "; <span class=\"key bound\">bound</span> " << (first.upper ? "at most " : "at least ")
        << html_text(points(first.bound * first.unit_scale) + " " + first.unit);
  out << "; <span class=\"key reference\">the reference's run</span>" << (frame.reference.t.empty() ? " (not recorded)" : "")
      << "</p>\n<div class=\"multiples\">\n";
  Json panels = Json::array();
  for (const auto& [label, colour] : groups) {
    std::vector<SmallCurve> curves;
    std::vector<std::size_t> who;
    for (const Entry& e : entries) {
      const std::string group = e.passed ? "passed" : e.group.empty() ? "failed, no known mistake named" : e.group;
      if (group != label) continue;
      who.push_back(e.student);
      const auto same = [&](const SmallCurve& c) { return c.series.t == e.run->student.t && c.series.v == e.run->student.v; };
      const auto it = std::find_if(curves.begin(), curves.end(), same);
      if (it != curves.end()) ++it->students;
      else curves.push_back(SmallCurve{e.run->student, colour, 1});
    }
    if (who.empty()) continue;
    out << "<div class=\"panel\" data-group=\"" << html_text(label) << "\" data-students=\"" << who.size() << "\">"
        << svg_small_multiple(frame, curves, kPanelWidth, kPanelHeight) << "<div class=\"caption\"><span class=\"swatch\" style=\"background:"
        << colour << "\"></span>" << html_text(label) << " (" << who.size() << ")</div></div>\n";
    panels.push_back(Json{{"group", label}, {"students", ids(who)}});
  }
  out << "</div>\n</figure>\n";
  data.push_back(Json{{"test", test}, {"statistic", statistic}, {"panels", panels}});
}

void runs_section(std::ostream& out, const std::vector<ClassStudent>& students, const std::vector<MistakeRow>& ranked, Json& data) {
  out << "<section id=\"runs\">\n<h2>The simulated tests: every student's run over the reference's</h2>\n"
      << "<p>One plot per known mistake, in its colour (the table above), then the failed runs with no mistake named "
      << "(black), then the passed ones (grey); the reference's run in blue, the bound dashed green, the start the test "
      << "does not judge shaded. Identical runs are drawn once.</p>\n";
  Json figures = Json::array();
  for (const std::string& test : test_order(students)) {
    std::vector<std::string> statistics;  // the test's judged runs, in order
    std::map<std::string, std::vector<Entry>> entries;
    for (std::size_t i = 0; i < students.size(); ++i)
      for (const ClassTest& t : students[i].tests) {
        if (test_key(t) != test) continue;
        for (const ClassRun& r : t.runs) {
          if (r.student.t.empty()) continue;
          if (!entries.count(r.statistic)) statistics.push_back(r.statistic);
          entries[r.statistic].push_back(Entry{i, &r, t.mistake, t.passed()});
        }
      }
    for (const std::string& statistic : statistics) run_figure(out, test, statistic, entries[statistic], ranked, figures);
  }
  out << "</section>\n";
  data["runs"] = std::move(figures);
}

// Every student with their total, linked to their report.
void students_section(std::ostream& out, const std::vector<ClassStudent>& students, const ClassPageOptions& o) {
  out << "<section id=\"students\">\n<h2>Every student</h2>\n<p>";
  for (std::size_t i = 0; i < students.size(); ++i)
    out << (i ? ", " : "") << student_html(students, i, o) << " " << points(students[i].score) << "/"
        << points(students[i].max_score);
  out << "</p>\n</section>\n";
}

// The data as JSON inside <script type="application/json">: no < > & raw, so that no text can
// close the element.
std::string script_json(const Json& data) {
  std::string out;
  for (const char c : data.dump(-1, ' ', false, Json::error_handler_t::replace)) {
    if (c == '<') out += "\\u003c";
    else if (c == '>') out += "\\u003e";
    else if (c == '&') out += "\\u0026";
    else out += c;
  }
  return out;
}

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:1em auto;max-width:96em;padding:0 1em;color:#222}"
    "h2{border-bottom:1px solid #ccc;padding-bottom:.2em}h3{font-size:1em;margin:.6em 0 .2em}"
    "table{border-collapse:collapse;font-size:.9em;margin:.4em 0}td,th{border:1px solid #ddd;padding:.15em .5em;"
    "vertical-align:top;text-align:left}.bar{display:inline-block;height:.8em;background:#1f77b4}"
    ".swatch{display:inline-block;width:.9em;height:.9em;margin-right:.3em;vertical-align:middle}"
    ".problem{display:inline-block;vertical-align:top;margin-right:2em}.multiples{display:flex;flex-wrap:wrap;gap:.5em}"
    ".panel{font-size:.8em}.caption{max-width:300px}.key.reference{color:#1f77b4}.key.bound{color:#2ca02c}"
    "figure{margin:.5em 0 1.2em}";

}  // namespace

void write_class_page(std::ostream& out, const std::vector<ClassStudent>& students, const ClassPageOptions& options) {
  const std::vector<MistakeRow> ranked = ranked_mistakes(students);
  Json data;
  Json who = Json::array();
  for (std::size_t i = 0; i < students.size(); ++i) {
    Json s{{"id", i + 1}, {"score", students[i].score}, {"max_score", students[i].max_score}};
    if (!options.anonymous) s["name"] = students[i].name;
    who.push_back(std::move(s));
  }
  data["students"] = std::move(who);
  data["anonymous"] = options.anonymous;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>opspace: the class</title>\n<style>"
      << kStyle << "</style>\n</head>\n<body>\n<h1>The class: " << students.size() << " student(s)</h1>\n"
      << "<p>" << (options.source.empty() ? "Built from each student's results.json" : html_text(options.source))
      << " (docs/instructor.md, \"Seeing the class\")"
      << (options.anonymous          ? "; students numbered in the order of their folders' names"
          : options.source.empty() ? "; each name links to the student's report"
                                   : "")
      << ".</p>\n";
  attention_section(out, students, options, data);
  mistakes_section(out, students, ranked, options, data);
  runs_section(out, students, ranked, data);
  problems_section(out, students, data);
  students_section(out, students, options);
  out << "<script type=\"application/json\" id=\"class-data\">" << script_json(data) << "</script>\n</body>\n</html>\n";
}

namespace {

// A CSV field: quoted, quotes doubled, a line break written \n, a formula's first character
// behind a ' (OWASP's advice against CSV injection, as deploy/scores.cmake does).
std::string csv(std::string field) {
  for (std::size_t at = field.find('\n'); at != std::string::npos; at = field.find('\n', at)) field.replace(at, 1, "\\n");
  for (std::size_t at = field.find('\r'); at != std::string::npos; at = field.find('\r', at)) field.replace(at, 1, "\\r");
  if (!field.empty() && std::string("=+-@\t").find(field[0]) != std::string::npos) field = "'" + field;
  std::string out = "\"";
  for (const char c : field) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

void write_mistakes_csv(std::ostream& out, const std::vector<ClassStudent>& students, const ClassPageOptions& options) {
  out << "rank,problem,mistake,students,tests,who\n";
  const std::vector<MistakeRow> ranked = ranked_mistakes(students);
  for (std::size_t k = 0; k < ranked.size(); ++k) {
    const MistakeRow& m = ranked[k];
    std::string tests, who;
    for (const auto& [test, count] : m.tests) tests += (tests.empty() ? "" : "; ") + test + " (" + std::to_string(count) + ")";
    for (const std::size_t i : m.students) who += (who.empty() ? "" : "; ") + (options.anonymous ? "student " + std::to_string(i + 1) : students[i].name);
    out << k + 1 << "," << csv(m.problem) << "," << csv(m.mistake) << "," << m.students.size() << "," << csv(tests) << ","
        << csv(who) << "\n";
  }
}

}  // namespace opspace::grading
