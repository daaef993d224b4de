// Machine-readable grades: Gradescope's results.json (written by nlohmann-json) and JUnit XML.
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <sstream>

#include "grader.hpp"
#include "student_text.hpp"

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

std::string feedback(const TestResult& r) {
  std::string text;
  for (const std::string& f : r.findings) text += "- " + f + "\n";
  if (r.score < r.test->points && !r.interrupted && !r.diagnosed) text += "hint: " + r.test->hint + "\n";
  if (!r.printed.empty()) text += "your code printed:\n" + quote_block(r.printed, "");
  return text;
}

bool hidden_test(const std::string& name, const std::vector<std::string>& hidden) {
  for (const std::string& h : hidden) {
    if (!h.empty() && name.find(h) != std::string::npos) return true;
  }
  return false;
}

}  // namespace

void write_gradescope(std::ostream& out, const std::vector<ProblemResult>& problems, double seconds,
                      const std::vector<std::string>& hidden) {
  double score = 0.0, max_score = 0.0;
  std::ostringstream summary;
  for (const ProblemResult& p : problems) {
    score += p.score;
    max_score += p.max_score;
    summary << "Problem " << p.problem->key << ": " << p.score << " / " << p.max_score << "\n";
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
      const std::string name = p.problem->key + " " + r.test->name;
      tests.push_back(Json{{"name", name},
                           {"score", number(r.score)},
                           {"max_score", number(r.test->points)},
                           {"status", r.score >= r.test->points ? "passed" : "failed"},
                           {"output", feedback(r)},
                           {"visibility", hidden_test(name, hidden) ? "hidden" : "visible"}});
    }
  }
  const Json results{{"score", number(score)},          {"max_score", number(max_score)},
                     {"execution_time", number(seconds)}, {"output", summary.str()},
                     {"visibility", "visible"},           {"tests", std::move(tests)}};
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
          << xml_text(r.test->name) << "\"";
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
