// Machine-readable grades: Gradescope's results.json and JUnit XML.
#include <cstdio>
#include <ostream>
#include <sstream>

#include "grader.hpp"
#include "student_text.hpp"

namespace opspace::grading {

namespace {

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buffer[8];
          std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
          out += buffer;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
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
  out.precision(10);
  out << "{\n  \"score\": " << score << ",\n  \"max_score\": " << max_score
      << ",\n  \"execution_time\": " << seconds << ",\n  \"output\": " << json_string(summary.str())
      << ",\n  \"visibility\": \"visible\",\n  \"tests\": [";
  bool first = true;
  for (const ProblemResult& p : problems) {
    for (const TestResult& r : p.results) {
      const std::string name = p.problem->key + " " + r.test->name;
      out << (first ? "\n" : ",\n") << "    {\"name\": " << json_string(name) << ", \"score\": " << r.score
          << ", \"max_score\": " << r.test->points << ", \"status\": \""
          << (r.score >= r.test->points ? "passed" : "failed") << "\", \"output\": " << json_string(feedback(r))
          << ", \"visibility\": \"" << (hidden_test(name, hidden) ? "hidden" : "visible") << "\"}";
      first = false;
    }
  }
  out << "\n  ]\n}\n";
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
