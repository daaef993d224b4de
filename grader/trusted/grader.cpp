// hw2-grade's pipeline, stage by stage (README.md in this folder): the command line, the
// sandbox's check, the build of every chosen problem's runner, the run and judging of its tests,
// the report and the results files. Each stage's work is in its folder; this file only orders it.
#include "grader.hpp"

#include <unistd.h>

#include <chrono>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "build/runner_builds.hpp"
#include "build/runner_cache.hpp"
#include "grader_options.hpp"
#include "judge/grade_problems.hpp"
#include "judge/grading.hpp"
#include "judge/reference_store.hpp"
#include "report/report.hpp"
#include "report/results_files.hpp"
#include "sandbox/grading_group.hpp"
#include "sandbox/interrupt.hpp"
#include "sandbox/sandbox.hpp"
#include "sandbox/sandbox_check.hpp"

namespace opspace::grading {

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr double kDefaultTimeout = 300.0;  // everything runs about 15 times slower under the sanitizers
#else
constexpr double kDefaultTimeout = 30.0;
#endif

double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<std::string> keys_of(const std::vector<const Problem*>& problems) {
  std::vector<std::string> keys;
  for (const Problem* problem : problems) keys.push_back(problem->key);
  return keys;
}

}  // namespace

int grader_main(int argc, char** argv, const std::string& default_exercises) {
  // The command line.
  GraderOptions options;
  options.exercises = default_exercises;
  options.timeout = kDefaultTimeout;
  int exit_code = 0;
  if (!parse_grader_options(argc, argv, options, exit_code)) return exit_code;
  if (!options.isolate && geteuid() == 0) {
    std::cerr << argv[0] << ": --no-isolation would run a student's code as root: refused\n";
    return 2;
  }

  // The sandbox: this grading's share of the machine (before any child: grading_group.hpp), the
  // account that runs the student's code, and whether the sandbox holds whole here.
  become_subreaper();
  clean_up_when_interrupted();
  const GradingGroups groups = options.isolate ? join_grading_groups(grading_budget(options.memory_mib)) : GradingGroups{};
  Account account;
  try {
    account = options.isolate ? grading_account(options.user) : Account{};
  } catch (const std::exception& e) {
    std::cerr << argv[0] << ": " << e.what() << "\n";
    return 2;
  }
  std::string unprotected;
  if (!may_grade_here({options.isolate, options.allow_unprotected, options.check_sandbox}, account, argv[0], unprotected))
    return kExitUnprotected;
  if (options.check_sandbox) return print_sandbox_check(groups, unprotected);

  // What is graded: the chosen problems, with this grading's seed.
  if (options.seed == 0) options.seed = drawn_seed();
  set_run_seed(options.seed);
  const std::vector<Problem> suite = graded_suite();
  const std::vector<const Problem*> chosen = chosen_problems(suite, options.only_problem);
  if (chosen.empty()) {
    std::cerr << argv[0] << ": no problem '" << options.only_problem << "'\n";
    return grader_usage(std::cerr, argv[0], kDefaultTimeout, 2);
  }
  Toolchain toolchain;
  try {
    toolchain = load_toolchain(OPSPACE_RUNNER_TOOLCHAIN);
  } catch (const std::exception& e) {
    std::cerr << "hw2-grade: " << e.what() << "\n";
    return 1;
  }
  // The reference's runs of the figures, kept for every later grading by this grader.
  const std::string cache_dir = options.cache_dir.empty() ? std::string(OPSPACE_GRADING_CACHE) : options.cache_dir;
  set_reference_store(cache_dir + "/reference-" + toolchain.fingerprint);
  if (!unprotected.empty())
    std::cout << "UNPROTECTED: " << unprotected << ": the code graded ran with this grader's rights\n";
  std::cout << "opspace grader: problem set 2, " << options.exercises << " (seed " << options.seed << ")\n"
            << std::flush;

  // Build: each problem's runner from its exercise file, in the sandbox.
  const auto start = std::chrono::steady_clock::now();
  std::cerr << "building the runners of " << chosen.size() << " problem(s)...\n";
  const std::vector<std::string> keys = keys_of(chosen);
  const std::vector<BuiltRunner> built =
      build_runners(keys, toolchain, options.exercises, {cache_dir, account, options.isolate, 180.0});
  const double build_seconds = since(start);
  print_built(keys, built);

  // Run and judge: each problem's tests against its runner.
  const auto grading_start = std::chrono::steady_clock::now();
  Grades grades;
  if (!grade_in_run_folder(chosen, built, grading_settings(options, chosen, account), account, grades)) return 1;
  std::cerr << prune_runner_cache(cache_dir, options.cache_mib << 20).line(options.cache_mib << 20) << "\n";
  const double grading_seconds = since(grading_start), seconds = since(start);

  // Report: the score table, its footer, and the results files asked for.
  print_report(std::cout, grades.results, options.hidden, options.seed);
  print_footer(std::cout, build_seconds, grading_seconds, options.seed, options.isolate, grades.started,
               grades.protections);
  return write_results_files(results_files(options, !unprotected.empty()), grades.results, seconds) ? 0 : 1;
}

}  // namespace opspace::grading
