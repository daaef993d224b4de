/// @file grader.hpp
/// The grading command behind hw2-grade, the trusted side: it builds each problem's runner
/// from that problem's exercise file, asks the runner for the student's values, judges them
/// against its oracles, and writes the report, results.json and JUnit XML. It never links,
/// loads or runs a student's code in its own process.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "report/report.hpp"
#include "build/runner_cache.hpp"

namespace opspace::grading {

/// What hw2-grade's command line sets (docs/grader.md).
struct GraderOptions {
  std::string only_problem;         ///< empty: every problem
  std::string exercises;            ///< the folder of p1a.cpp ... p4.cpp to grade
  double timeout = 30.0;            ///< seconds per test for every request to the runner
  std::map<std::string, double> problem_timeout;  ///< a problem's own limit (--timeout KEY=SECONDS)
  std::string gradescope_path;      ///< results.json, if not empty
  std::string prairielearn_path;    ///< PrairieLearn's results.json (--prairielearn), if not empty
  std::string junit_path;           ///< JUnit XML, if not empty
  std::string html_path;            ///< the report as a page (report_html.hpp), if not empty
  std::vector<std::string> hidden;  ///< tests whose name contains one of these are hidden
  std::string hidden_as = "after_published";  ///< their visibility in results.json (--hidden-visibility)
  std::string gradescope_format = "html";     ///< results.json's tests' output_format (--gradescope-format)
  bool isolate = true;              ///< the sandbox (false: debugging only)
  std::uint64_t seed = 0;           ///< random inputs; 0: draw a new seed
  std::string user;                 ///< when root: a named account that runs student code (empty: the grading's own)
  bool allow_unprotected = false;   ///< grade even where the sandbox is incomplete (--unprotected)
  bool check_sandbox = false;       ///< only say whether the sandbox holds whole (--check-sandbox)
  unsigned long long memory_mib = 0;  ///< the grading's memory budget (--memory; 0: the machine's)
  unsigned long long cache_mib = kDefaultCacheMib;  ///< the runners' cache bound (--cache-limit)
  std::string cache_dir;            ///< the runners' cache (--cache; empty: the build's)
  unsigned jobs = 0;                ///< problems graded at once (--jobs); 0: jobs_by_default()
  /// A problem graded with a core to spare (jobs at least twice the problems) makes some of its
  /// listed runs on a second runner (runs_ahead.hpp); false: one runner each (--one-runner).
  bool second_runner = true;
};

/// Reads hw2-grade's command line into `options` (whose timeout is the default on entry).
/// Returns false when the program should exit with `exit_code` (--help: 0, a bad option: 2,
/// with the reason on stderr).
bool parse_grader_options(int argc, char** argv, GraderOptions& options, int& exit_code);

/// The usage text; returns `code`.
int grader_usage(std::ostream& out, const char* program, double default_timeout, int code);

/// The time limit of each test of problem `key`: its own (--timeout KEY=SECONDS), else --timeout's.
double timeout_of(const GraderOptions& options, const std::string& key);

/// How many problems are graded at once without --jobs: one per core where the runners share
/// no process limit (`shared_account` false: the grader is not root, or the sandbox is off),
/// else one. As root a grading's runners all run as its account, under one RLIMIT_NPROC that a
/// runner's threads could fill while another problem's runner starts (docs/grader.md).
unsigned jobs_by_default(bool shared_account);

/// What results.json hides, and the grader's record it carries (docs/grader.md).
struct GradescopeSettings {
  std::vector<std::string> hidden;            ///< tests whose "<key> <name>" contains one of these
  std::string hidden_as = "after_published";  ///< their visibility: after_published or after_due_date
  std::uint64_t seed = 0;                     ///< the run's seed (a retry replays it)
  /// The tests' output_format: "html" (each failed simulated test's plot as a PNG, a wrong
  /// matrix as a table, every text escaped) or "text" (the plot as a table of samples).
  std::string format = "html";
  bool unprotected = false;  ///< the code graded ran without the whole sandbox (--unprotected, --no-isolation)
};

/// Gradescope's results.json: score (the whole grade), max_score, execution_time, output (one
/// line per problem counting the tests shown), output_format "text", and tests[] with name,
/// score, max_score, status, output (in `settings.format`) and visibility (`hidden_as` for the hidden tests, else
/// "visible"); every text HTML-escaped. extra_data.grader holds the seed and grader_faults().
void write_gradescope(std::ostream& out, const std::vector<ProblemResult>& problems, double seconds,
                      const GradescopeSettings& settings);

/// What PrairieLearn's results.json hides, and the run's seed.
struct PrairieLearnSettings {
  std::vector<std::string> hidden;  ///< tests whose "<key> <name>" contains one of these: left out
  std::uint64_t seed = 0;           ///< the run's seed, for each failed simulated test's replay
};

/// PrairieLearn's external grader's results.json (its external grading guide): gradable true,
/// score the whole grade in [0, 1] (hidden tests included), message (one line per problem,
/// counting the tests shown), and tests[] with name, description, points, max_points, message,
/// output and images[] (each failed simulated test's plots as data:image/png URLs); the hidden
/// tests left out. Kept under kPrairieLearnLimit bytes: pictures are dropped, last first, then
/// outputs cut, each with a note in message.
void write_prairielearn(std::ostream& out, const std::vector<ProblemResult>& problems, double seconds,
                        const PrairieLearnSettings& settings);

/// PrairieLearn's bound on results.json: 1 MB. A decimal megabyte, the smaller reading.
constexpr std::size_t kPrairieLearnLimit = 1000 * 1000;

/// A test's feedback as text for a page that shows its pictures beside it: the judged values,
/// findings, hint, replay command, prints and wrong matrix's grid, without the runs' tables (a
/// test not written yet: its one line). Gradescope's html output and PrairieLearn's share it.
std::string feedback_beside_pictures(const TestResult& r, std::uint64_t seed);

/// A figure's caption: the quantity, its unit, which run is which colour, and what is judged.
std::string figure_caption(const RunFigure& f);

/// The tests and problems lost to the grader's own failures (a program it could not start, a
/// runner it could not build), never to the student's code: scripts/regrade grades those again.
/// Counted from ProblemResult::grader_fault and TestResult::grader_fault, never from a text.
int grader_faults(const std::vector<ProblemResult>& problems);

/// JUnit XML: one <testsuite> per problem, one <testcase> per test, <failure> with the findings.
void write_junit(std::ostream& out, const std::vector<ProblemResult>& problems, double seconds);

/// The whole command: parses argv, grades the exercise files in `default_exercises` (or
/// --exercises), prints, writes the requested files. Returns the exit code: 0 when grading ran
/// (whatever the score), 2 for a bad command line, 1 when an output file cannot be written or
/// the grader itself is broken.
int grader_main(int argc, char** argv, const std::string& default_exercises);

}  // namespace opspace::grading
