// Machine-readable grades: Gradescope's results.json (written by nlohmann-json) and JUnit XML.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <sstream>

#include "report/class_record.hpp"
#include "report/autograder_output.hpp"
#include "report/plot_png.hpp"
#include "report/report_html.hpp"
#include "common/student_text.hpp"

namespace opspace::grading {

namespace {

using Json = nlohmann::ordered_json;  // keys in the order written

/// A score or a time as before nlohmann-json: 10 significant digits, and an integer without a
/// fraction (deploy/scores.cmake and tests/tamper/run_case.cmake add scores with CMake's integer
/// math). NaN and infinities, which JSON cannot write, become null.
Json number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  const double rounded = std::strtod(text, nullptr);
  if (std::isfinite(rounded) && rounded == std::floor(rounded) && std::abs(rounded) < 1e15)
    return static_cast<std::int64_t>(rounded);
  return rounded;
}

std::string xml_text(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// A wrong matrix or vector's entries as its grid of text, each "expected / yours", the wrong ones
// marked "!" after: for a <pre> (Gradescope's sanitizer may strip a <table>, never a <pre>).
std::string entry_grid(const EntryTable& e) {
  if (e.what.empty() || e.expected.size() > 100) return "";
  const double scale = std::max(1.0, e.expected.cwiseAbs().maxCoeff());
  const auto cell = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return std::string(b);
  };
  std::vector<std::string> cells;
  std::size_t width = 0;
  for (Eigen::Index i = 0; i < e.expected.rows(); ++i)
    for (Eigen::Index j = 0; j < e.expected.cols(); ++j) {
      const double x = e.expected(i, j), c = e.computed(i, j);
      const bool wrong = !std::isfinite(c) || std::abs(c - x) > e.tol * scale;
      cells.push_back(cell(x) + " / " + cell(c) + (wrong ? " !" : ""));
      width = std::max(width, cells.back().size());
    }
  std::string out = e.what + ", each entry expected / yours (! wrong):\n";
  std::size_t k = 0;
  for (Eigen::Index i = 0; i < e.expected.rows(); ++i) {
    out += "  [";
    for (Eigen::Index j = 0; j < e.expected.cols(); ++j, ++k)
      out += " " + cells[k] + std::string(width - cells[k].size(), ' ') + (j + 1 < e.expected.cols() ? " |" : "");
    out += " ]\n";
  }
  return out;
}

// A test not written yet (TestResult::not_written): its one line, and what the code printed. The
// untouched stubs' 41 tests took 17 screens of Gradescope's page with their 19 plots.
std::string not_written(const TestResult& r) {
  std::string text = "- " + r.findings.back() + "\n";
  if (!r.printed.empty()) text += "your code printed:\n" + quote_block(r.printed, "");
  return text;
}

// What a test judged, its findings and, where it shows (shows_hint), its hint: every text's head.
std::string judged_and_findings(const TestResult& r) {
  std::string text;
  for (const std::string& j : r.judged) text += "judged: " + j + "\n";
  for (const std::string& f : r.findings) text += "- " + f + "\n";
  if (shows_hint(r)) text += "hint: " + r.test->hint + "\n";
  return text;
}

// The findings and hint; for a failed simulated test with `seed`, its runs as text tables
// (results.json shows text alone: docs/grader.md) and the command that replays it.
std::string feedback(const TestResult& r, std::uint64_t seed = 0) {
  if (r.not_written) return not_written(r);
  std::string text = judged_and_findings(r);
  const bool failed = r.score < r.test->points;
  if (failed) text += entry_grid(r.table);
  if (failed && seed != 0) {
    for (const RunFigure& f : r.figures) text += run_table(f);
    const std::string replay = replay_command(*r.test, seed);
    if (!replay.empty()) text += "replay it on your machine: " + replay + "\n";
  }
  if (!r.printed.empty()) text += "your code printed:\n" + quote_block(r.printed, "");
  return text;
}

// A figure for Gradescope: its caption as text and its plot as a PNG in a data: URI, the form
// Gradescope's sanitized HTML keeps (docs/grader.md).
std::string figure_html(const RunFigure& f) {
  const std::string caption = figure_caption(f);
  std::string alt;  // an attribute's value: its quotes escaped too
  for (const char c : html_escape(f.quantity)) alt += c == '"' ? std::string("&quot;") : std::string(1, c);
  const std::string png = png_plot(f);  // empty in a grader built without cairo: the caption alone
  if (png.empty()) return "<p>" + html_escape(caption) + "</p>\n";
  return "<p>" + html_escape(caption) + "</p>\n<img alt=\"" + alt + "\" src=\"data:image/png;base64," + base64(png) +
         "\">\n";
}

// feedback() as Gradescope's HTML: the text in a <pre> (for a failed test with its wrong matrix's
// grid), then each figure of a failed test as a picture (the text tables of the runs are left
// out). Only <pre>, <p> and <img> with alt and a data:image/png source: what the strictest
// sanitizer documented for Gradescope's Rails keeps (docs/grader.md).
std::string feedback_html(const TestResult& r, std::uint64_t seed) {
  std::string out = "<pre>" + html_escape(feedback_beside_pictures(r, seed)) + "</pre>\n";
  if (r.score >= r.test->points) return out;
  for (const RunFigure& f : r.figures) out += figure_html(f);
  return out;
}

// Gradescope's tags of a test: the known mistake named for it, if any.
Json tags(const TestResult& r) {
  Json out = Json::array();
  if (!r.mistake.empty()) out.push_back(html_escape("mistake: " + r.mistake));
  return out;
}

// What the student reads of a hidden test's problem: when the hidden tests appear.
std::string shown_when(const std::string& hidden_as) {
  return hidden_as == "after_due_date" ? "after the due date" : "when your instructor publishes the grades";
}

}  // namespace

std::string feedback_beside_pictures(const TestResult& r, std::uint64_t seed) {
  if (r.not_written) return not_written(r);
  std::string text = judged_and_findings(r);
  const bool failed = r.score < r.test->points;
  const std::string replay = failed && seed != 0 ? replay_command(*r.test, seed) : "";
  if (!replay.empty()) text += "replay it on your machine: " + replay + "\n";
  if (!r.printed.empty()) text += "your code printed:\n" + quote_block(r.printed, "");
  if (failed) text += entry_grid(r.table);
  return text;
}

std::string figure_caption(const RunFigure& f) {
  std::string caption = f.quantity + (f.unit.empty() ? "" : " (" + f.unit + ")") +
                        ": your run in red, the reference's in blue";
  if (std::isfinite(f.bound)) caption += ", the bound dashed green";
  if (f.judged_from > 0.0) caption += "; the shaded start is not judged";
  return caption + ". Judged: " + f.judged + ".";
}

// Counted from the faults typed where they happened (fault.hpp), never from a text: a failure
// the submission caused may read like the grader's, and only the grader's buy a second grading.
int grader_faults(const std::vector<ProblemResult>& problems) {
  int faults = 0;
  for (const ProblemResult& p : problems) {
    if (p.grader_fault) {
      ++faults;  // the problem, once: its tests were never run
      continue;
    }
    const auto grader_fault = [](const TestResult& r) { return r.grader_fault; };
    faults += static_cast<int>(std::count_if(p.results.begin(), p.results.end(), grader_fault));
  }
  return faults;
}

void write_gradescope(std::ostream& out, const std::vector<ProblemResult>& problems, double seconds,
                      const GradescopeSettings& settings) {
  double score = 0.0, max_score = 0.0;
  std::ostringstream summary;
  for (const ProblemResult& p : problems) {
    score += p.score;
    max_score += p.max_score;
    // The student's lines count the tests they see: a hidden test's points would tell them
    // what it gave.
    const ShownScore shown = shown_score(p, settings.hidden);
    summary << "Problem " << p.problem->key << ": " << format_points(shown.score) << " / "
            << format_points(shown.max_score);
    if (shown.hidden_tests > 0) {
      summary << " in the tests shown (" << shown.hidden_tests << " hidden test" << (shown.hidden_tests == 1 ? "" : "s")
              << " of " << format_points(shown.hidden_points) << " points "
              << (shown.hidden_tests == 1 ? "appears " : "appear ") << shown_when(settings.hidden_as)
              << ")";
    }
    summary << "\n";
    if (!p.failure.empty()) {
      const std::size_t end = p.failure.find('\n');
      summary << "  " << p.failure.substr(0, end) << "\n";
      if (end != std::string::npos) summary << quote_block(p.failure.substr(end + 1), "    ");
    }
    if (!p.warnings.empty()) summary << "  compiler warnings:\n" << quote_block(p.warnings, "    ");
  }
  Json tests = Json::array();
  for (const ProblemResult& p : problems) {
    for (const TestResult& r : p.results) {
      tests.push_back(Json{{"name", p.problem->key + " " + r.test->title},
                           {"name_format", "text"},
                           {"score", number(r.score)},
                           {"max_score", number(r.test->points)},
                           {"status", r.score >= r.test->points ? "passed" : "failed"},
                           {"output", settings.format == "text" || r.not_written ? html_escape(feedback(r, settings.seed))
                                                                                 : feedback_html(r, settings.seed)},
                           // A test not written yet is one line of text: no <pre> and its margins.
                           {"output_format", r.not_written ? "text" : settings.format},
                           {"tags", tags(r)},
                           {"extra_data", class_record(p, r)},
                           {"visibility", is_hidden(p, r, settings.hidden) ? settings.hidden_as : "visible"}});
    }
  }
  // The score is the whole grade, hidden tests included: it is what Gradescope's gradebook
  // takes. A test marked after_due_date or after_published keeps the total from the student
  // until then (Gradescope's autograder specification); the output's lines count the tests
  // shown. Every text is "text" (shown as it is, never rendered) and HTML-escaped besides.
  // extra_data.grader is the grader's own record, for scripts/regrade: the seed of the run, the
  // tests or problems lost to the grader's own failures (never read from the student's text) and
  // whether the code ran without the sandbox; each test's extra_data is the class page's
  // (class_record.hpp).
  const Json results{{"score", number(score)},
                     {"max_score", number(max_score)},
                     {"execution_time", number(seconds)},
                     {"output", html_escape(summary.str())},
                     {"output_format", "text"},
                     {"test_output_format", settings.format},
                     {"test_name_format", "text"},
                     {"visibility", "visible"},
                     {"stdout_visibility", "hidden"},
                     {"extra_data", Json{{"grader", Json{{"seed", settings.seed},
                                                         {"grader_faults", grader_faults(problems)},
                                                         {"unprotected", settings.unprotected}}}}},
                     {"tests", std::move(tests)}};
  // The texts are the student's, already escaped (student_text.hpp): replace, never throw on,
  // bytes that are not UTF-8, so that no text can stop the file from being written.
  out << results.dump(2, ' ', false, Json::error_handler_t::replace) << "\n";
}

void write_junit(std::ostream& out, const std::vector<ProblemResult>& problems, double seconds) {
  std::size_t tests = 0, failures = 0;
  for (const ProblemResult& p : problems) {
    for (const TestResult& r : p.results) {
      ++tests;
      failures += r.score < r.test->points ? 1 : 0;
    }
  }
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"opspace problem set 2\" tests=\"" << tests
      << "\" failures=\"" << failures << "\" time=\"" << seconds << "\">\n";
  for (const ProblemResult& p : problems) {
    std::size_t problem_failures = 0;
    for (const TestResult& r : p.results) problem_failures += r.score < r.test->points ? 1 : 0;
    out << "  <testsuite name=\"problem " << xml_text(p.problem->key) << "\" tests=\"" << p.results.size()
        << "\" failures=\"" << problem_failures << "\">\n";
    for (const TestResult& r : p.results) {
      out << "    <testcase classname=\"problem " << xml_text(p.problem->key) << "\" name=\""
          << xml_text(r.test->title) << "\"";
      if (r.score >= r.test->points) {
        out << "/>\n";
        continue;
      }
      out << ">\n      <failure message=\"" << r.score << " of " << r.test->points << " points\">"
          << xml_text(feedback(r)) << "</failure>\n    </testcase>\n";
    }
    out << "  </testsuite>\n";
  }
  out << "</testsuites>\n";
}

}  // namespace opspace::grading
