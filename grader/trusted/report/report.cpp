#include "report/report.hpp"

#include "common/student_text.hpp"

#include <cstdio>
#include <ostream>
#include <string>

namespace opspace::grading {

namespace {

// What the student's side wrote (already escaped: student_text.hpp), each line behind "| " so
// that it can never pass for a line of the report.
std::string quoted(const std::string& text) { return quote_block(text, "            "); }

// A build failure: the grader's line, then the lines of the student's file it quotes.
void print_failure(std::ostream& out, const std::string& failure) {
  const std::size_t end = failure.find('\n');
  out << "  ! " << failure.substr(0, end) << "\n";
  if (end != std::string::npos) out << quoted(failure.substr(end + 1));
}

// How many tests the report leaves out, and their points; never what they earned.
std::string hidden_note(int tests, double points) {
  return std::to_string(tests) + " hidden test" + (tests == 1 ? "" : "s") + " of " + format_points(points) +
         " points not shown: they count in the grade your instructor publishes";
}

// `text` between double quotes for bash: \ " $ ` escaped.
std::string bash_quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '\\' || c == '"' || c == '$' || c == '`') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string status(const TestResult& r) {
  if (r.score >= r.test->points) return "PASS";
  return r.score > 0.0 ? "PART" : "FAIL";
}

std::string replay_command(const GradedTest& test, std::uint64_t seed) {
  if (test.replay.empty()) return "";
  std::string command = "bash scripts/run " + test.replay + " --test " + bash_quoted(test.title);
  if (seed != 0) command += " --seed " + std::to_string(seed);
  return command;
}

bool is_hidden(const ProblemResult& problem, const TestResult& test, const std::vector<std::string>& hidden) {
  const std::string name = problem.problem->key + " " + test.test->title;
  for (const std::string& h : hidden) {
    if (!h.empty() && name.find(h) != std::string::npos) return true;
  }
  return false;
}

ShownScore shown_score(const ProblemResult& problem, const std::vector<std::string>& hidden) {
  ShownScore out;
  for (const TestResult& r : problem.results) {
    if (is_hidden(problem, r, hidden)) {
      ++out.hidden_tests;
      out.hidden_points += r.test->points;
    } else {
      out.score += r.score;
      out.max_score += r.test->points;
    }
  }
  return out;
}

void print_report(std::ostream& out, const std::vector<ProblemResult>& problems, const std::vector<std::string>& hidden,
                  std::uint64_t seed) {
  double total = 0.0, total_max = 0.0, hidden_points = 0.0;
  int hidden_tests = 0;
  for (const ProblemResult& p : problems) {
    const ShownScore shown = shown_score(p, hidden);
    out << "\nProblem " << p.problem->key << ": " << p.problem->title << "\n";
    for (const TestResult& r : p.results) {
      if (is_hidden(p, r, hidden)) continue;
      const std::string score = format_points(r.score) + "/" + format_points(r.test->points);
      out << "  " << status(r) << "  " << score << std::string(score.size() < 6 ? 6 - score.size() : 1, ' ')
          << r.test->title << "\n";
      if (r.not_written) {
        // One line: the judged values, the hint and the replay would only describe the stub.
        out << "          - " << r.findings.back() << "\n";
        if (!r.printed.empty()) out << "          your code printed:\n" << quoted(r.printed);
        continue;
      }
      for (const std::string& j : r.judged) out << "          judged: " << j << "\n";
      if (r.score < r.test->points) {
        for (const std::string& finding : r.findings) out << "          - " << finding << "\n";
        if (shows_hint(r)) out << "          hint: " << r.test->hint << "\n";
        const std::string replay = replay_command(*r.test, seed);
        if (!replay.empty()) out << "          replay it: " << replay << "\n";
      }
      if (!r.printed.empty()) out << "          your code printed:\n" << quoted(r.printed);
    }
    if (!p.failure.empty()) print_failure(out, p.failure);
    for (const std::string& note : p.notes) out << "  ! " << note << "\n";
    if (!p.warnings.empty()) out << "  compiler warnings (not counted):\n" << quoted(p.warnings);
    out << "  Problem " << p.problem->key << ": " << format_points(shown.score) << " / "
        << format_points(shown.max_score) << " points";
    if (shown.hidden_tests > 0) out << " in the tests shown (" << hidden_note(shown.hidden_tests, shown.hidden_points) << ")";
    out << "\n";
    total += shown.score;
    total_max += shown.max_score;
    hidden_tests += shown.hidden_tests;
    hidden_points += shown.hidden_points;
  }
  out << "\nScore per problem:\n";
  for (const ProblemResult& p : problems) {
    const ShownScore shown = shown_score(p, hidden);
    out << "  " << p.problem->key << "  " << format_points(shown.score) << " / " << format_points(shown.max_score) << "\n";
  }
  out << "Total: " << format_points(total) << " / " << format_points(total_max) << " points";
  if (hidden_tests > 0) out << " in the tests shown (" << hidden_note(hidden_tests, hidden_points) << ")";
  out << "\n";
  // Nothing earned in a whole grading: the first problem of the list is where to begin.
  if (total == 0.0 && hidden_tests == 0 && problems.size() > 1) {
    const Problem& first = *problems.front().problem;
    out << "Where to start: open exercises/p" << first.key << ".cpp (" << first.title << "; guide problems/" << first.key
        << "/guide.md)\nand grade it alone: bash scripts/grade --problem " << first.key << "\n";
  }
}

void print_footer(std::ostream& out, double build_seconds, double grading_seconds, std::uint64_t seed, bool isolate,
                  bool started, const Protections& protections) {
  char times[200];
  std::snprintf(times, sizeof times, "Built in %.1f s, graded in %.1f s (seed %llu: --seed %llu replays these inputs)\n",
                build_seconds, grading_seconds, static_cast<unsigned long long>(seed),
                static_cast<unsigned long long>(seed));
  out << times;
  if (!isolate) {
    out << "Sandbox: off (--no-isolation)\n";
  } else if (started && !protections.missing().empty()) {
    out << "Sandbox: these protections were not available here: " << protections.missing() << " (docs/grader.md)\n";
  }
  out << std::flush;
}

}  // namespace opspace::grading
