/// @file grader_options.hpp
/// hw2-grade's command line, read into the settings of each stage of its pipeline (grader.cpp).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "build/runner_cache.hpp"
#include "judge/grade_problems.hpp"
#include "judge/graded_suite.hpp"
#include "report/results_files.hpp"
#include "sandbox/sandbox.hpp"

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

/// A seed for a grading's random inputs, 1 to 10^9 (short enough to type after --seed).
std::uint64_t drawn_seed();

/// The problems of `suite` that --problem chose (all without it), in the suite's order.
std::vector<const Problem*> chosen_problems(const std::vector<Problem>& suite, const std::string& only);

/// The settings of the run and judge stages (judge/grade_problems.hpp) for the problems
/// `chosen`, as `options` set them; `account` is the one that runs the student's code.
GradingSettings grading_settings(const GraderOptions& options, const std::vector<const Problem*>& chosen,
                                 const Account& account);

/// The files `options` asks for, and what they show.
ResultsFiles results_files(const GraderOptions& options, bool unprotected);

}  // namespace opspace::grading
