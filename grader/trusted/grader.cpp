#include "grader.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <random>
#include <thread>

#include "judge/graded_suite.hpp"
#include "sandbox/grading_group.hpp"
#include "sandbox/interrupt.hpp"
#include "judge/mistakes.hpp"
#include "judge/reference_store.hpp"
#include "run/remote_api.hpp"
#include "report/report_html.hpp"
#include "build/runner_build.hpp"
#include "build/runner_cache.hpp"
#include "run/runner_process.hpp"
#include "run/runs_ahead.hpp"
#include "sandbox/sandbox.hpp"
#include "common/student_text.hpp"

namespace opspace::grading {

namespace fs = std::filesystem;

namespace {

#if defined(__SANITIZE_ADDRESS__)
// Everything runs about 15 times slower under the sanitizers.
constexpr double kDefaultTimeout = 300.0;
// No leak check at exit (the sandbox forbids the ptrace it needs); the address-space limit
// cannot apply under AddressSanitizer, so its own limits stop a memory flood. A fault signal
// kills the runner as it does in a release build (AddressSanitizer would report it and exit 1,
// which the grader would take for an exit() call).
const std::vector<std::string> kRunnerEnv = {
    "ASAN_OPTIONS=detect_leaks=0:hard_rss_limit_mb=1024:max_allocation_size_mb=1024:allocator_may_return_null=1:"
    "handle_segv=0:handle_sigbus=0:handle_sigfpe=0:handle_sigill=0"};
#else
constexpr double kDefaultTimeout = 30.0;
const std::vector<std::string> kRunnerEnv = {};
#endif

// The exit code of a grader that refused to run code where the sandbox cannot be built.
constexpr int kExitUnprotected = 3;

// Writes through a temporary file and a rename: a reader sees the old file or the whole new one.
template <typename Writer>
bool write_file(const std::string& path, const char* what, Writer writer) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream file(temporary);
    if (file) writer(file);
    if (!file) {
      std::cerr << "hw2-grade: cannot write the " << what << " file " << path << "\n";
      return false;
    }
  }
  std::error_code ec;
  fs::rename(temporary, path, ec);
  if (ec) {
    std::cerr << "hw2-grade: cannot write the " << what << " file " << path << ": " << ec.message() << "\n";
    return false;
  }
  std::cout << what << ": " << path << "\n";
  return true;
}

std::string file_of(const std::string& key) { return "p" + key + ".cpp"; }

// `path` relative to the current folder when it lies below it ("out/grade/report.html").
std::string shown_path(const std::string& path) {
  std::error_code ec;
  const fs::path full = fs::weakly_canonical(fs::absolute(path, ec), ec);
  const fs::path here = fs::weakly_canonical(fs::current_path(ec), ec);
  if (ec) return path;
  const auto [f, h] = std::mismatch(full.begin(), full.end(), here.begin(), here.end());
  return h == here.end() ? full.lexically_relative(here).string() : full.string();
}

double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Calls `each(i)` for every i below `count`, `jobs` at once: this thread and jobs - 1 others
// take the next i in turn.
template <typename Each>
void at_once(std::size_t count, unsigned jobs, Each each) {
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t i = next++; i < count; i = next++) each(i);
  };
  std::vector<std::thread> threads;
  for (std::size_t j = 1; j < std::min<std::size_t>(jobs, count); ++j) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
}

// Builds the runners of `problems`, several at once (one compiler per core).
std::vector<BuiltRunner> build_all(const std::vector<const Problem*>& problems, const Toolchain& toolchain,
                                   const GraderOptions& options, const BuildSettings& settings) {
  std::vector<BuiltRunner> built(problems.size());
  at_once(problems.size(), std::max(1u, std::thread::hardware_concurrency()), [&](std::size_t i) {
    const std::string file = file_of(problems[i]->key);
    try {
      built[i] = build_runner(toolchain, problems[i]->key, options.exercises + "/" + file, "exercises/" + file, settings);
    } catch (const std::exception& e) {
      built[i].error = std::string("the grader could not build the runner: ") + e.what();
      built[i].fault = Fault::grader;
    }
  });
  return built;
}

// What this grading may use: --memory, else the machine's; processes for the builds running
// at once (one per core, each under its account's 64, build_tool.cpp) and as many runners (16
// each, runner_process.cpp).
GradingBudget grading_budget(const GraderOptions& options) {
  GradingBudget budget;
  budget.memory_bytes = options.memory_mib > 0 ? options.memory_mib << 20 : machine_memory();
  budget.processes = (64 + 16) * static_cast<unsigned long long>(std::max(1u, std::thread::hardware_concurrency()));
  return budget;
}

// A problem whose runner could not be built: every test 0, with the reason and no hint.
ProblemResult not_built(const Problem& problem, const BuiltRunner& built) {
  ProblemResult out;
  out.problem = &problem;
  out.failure = built.error;
  out.grader_fault = built.fault == Fault::grader;
  out.warnings = built.warnings;
  for (const GradedTest& t : problem.tests) {
    TestResult r;
    r.test = &t;
    r.findings = {"not graded: " + built.error.substr(0, built.error.find('\n'))};
    r.interrupted = true;
    r.grader_fault = out.grader_fault;
    out.results.push_back(r);
    out.max_score += t.points;
  }
  return out;
}

// Tests answered by a library answer the runner holds earn nothing; the note names the answer,
// what it costs and why (library_answers.hpp).
void apply_oracles(ProblemResult& result, const BuiltRunner& built) {
  for (const Oracle& oracle : built.called) {
    std::string names;
    int named = 0, more = 0;
    for (const std::string& owner : built.answers) {
      if (!belongs_to(owner, oracle)) continue;
      if (named++ < 3) names += (names.empty() ? "" : ", ") + escape_student_text(owner, false, false);
      else ++more;
    }
    if (more > 0) names += " and " + std::to_string(more) + " more";
    int tests = 0;
    double points = 0.0;
    for (TestResult& r : result.results) {
      const bool answered = oracle.tests.empty() ||
                            std::find(oracle.tests.begin(), oracle.tests.end(), r.test->id) != oracle.tests.end();
      if (!answered) continue;
      ++tests;
      points += r.test->points;
      r.score = 0.0;
      r.findings.insert(r.findings.begin(), "uses the library's own answer " + oracle.name + ": not counted");
      r.interrupted = true;
    }
    const std::string cost = "the " + std::to_string(tests) + " test" + (tests == 1 ? "" : "s") + " it answers (" +
                             format_points(points) + " points)";
    result.notes.push_back("not allowed in problem " + result.problem->key + ": exercises/" + file_of(result.problem->key) +
                           " reaches " + names + ", which computes " + oracle.what + ": " + cost +
                           " earn 0. Write it yourself (docs/grader.md)");
  }
  result.score = 0.0;
  for (const TestResult& r : result.results) result.score += r.score;
}

ProblemResult grade_problem(const Problem& problem, const BuiltRunner& built, const std::string& run_dir,
                            const GraderOptions& options, const Account& account, bool second_runner,
                            Protections& protections, bool& started) {
  if (!built.ok) return not_built(problem, built);
  // A folder of its own, holding its runner and nothing else: no other problem's runner (built
  // from the same student's other files, under other rules) is in its view.
  const std::string folder = run_dir + "/" + problem.key;
  const auto readable = fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                        fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec;
  fs::create_directory(folder);
  fs::permissions(folder, readable | fs::perms::owner_write);
  // As root: the grading's account's group alone may enter it (where the files' view is not
  // private, no other grading's runner can run this one).
  if (account.uid != 0 && chown(folder.c_str(), 0, account.gid) == 0)
    fs::permissions(folder, fs::perms::others_all, fs::perm_options::remove);
  const std::string binary = folder + "/runner-" + problem.key;
  fs::copy_file(built.binary, binary, fs::copy_options::overwrite_existing);
  fs::permissions(binary, readable);
  const RunnerConfig config{binary, folder, account, options.isolate, kRunnerEnv, built.runtime};
  RunnerProcess runner(config);
  const Hw2Api api = remote_api(problem.key, runner);
  ProblemResult out;
  out.problem = &problem;
  const std::vector<Mistake> catalogue = mistakes(problem.key);
  const double timeout = timeout_of(options, problem.key);
  // A second runner, started as the first (the same binary, folder, account and sandbox),
  // answering with the tests' identity: it makes its share of the problem's listed runs while
  // the tests run, and each is given to the first test that asks for it (runs_ahead.hpp).
  const std::vector<ListedRun> share = second_runner ? second_runner_share(problem.runs) : std::vector<ListedRun>{};
  std::optional<RunnerProcess> second;
  std::unique_ptr<RunsAhead> ahead;
  if (!share.empty()) {
    std::cerr << "a second runner makes " + std::to_string(share.size()) + " of problem " + problem.key + "'s " +
                     std::to_string(problem.runs.size()) + " simulated runs\n";  // one write
    second.emplace(config);
    Hw2Api second_api = remote_api(problem.key, *second);
    second_api.identity = api.identity;
    ahead = std::make_unique<RunsAhead>(share, second_api, *second, timeout);
  }
  out.results = run_tests(problem.tests, api, &runner, timeout, &catalogue);
  ahead.reset();  // its thread joined before its runner stops
  if (second) second->stop();
  runner.stop();
  // Whose fault each failure was: the runner knows (run_tests keeps only the failure's text).
  const std::vector<Fault>& faults = runner.test_faults();
  for (std::size_t i = 0; i < out.results.size() && i < faults.size(); ++i)
    out.results[i].grader_fault = faults[i] == Fault::grader;
  for (const TestResult& r : out.results) {
    out.score += r.score;
    out.max_score += r.test->points;
  }
  out.warnings = built.warnings;
  apply_oracles(out, built);
  if (runner.starts() > 0) {
    if (!started) protections = runner.protections();
    started = true;
  }
  return out;
}

// One problem's grade, and the protections of its runner if one started.
struct Graded {
  ProblemResult result;
  Protections protections;
  bool started = false;
};

// Grades `chosen`, `jobs` problems at once: each has its own runner, and its tests run in turn
// as before, so the results, kept in the problems' order, are those of one problem at a time.
std::vector<Graded> grade_all(const std::vector<const Problem*>& chosen, const std::vector<BuiltRunner>& built,
                              const std::string& run_dir, const GraderOptions& options, const Account& account,
                              unsigned jobs) {
  std::vector<Graded> graded(chosen.size());
  // A core to spare for each problem (one problem graded, --jobs 2): a second runner each.
  const bool second_runner = options.second_runner && jobs >= 2 * chosen.size();
  at_once(chosen.size(), jobs, [&](std::size_t i) {
    std::cerr << "grading problem " + chosen[i]->key + "...\n";  // one write: threads do not interleave it
    Graded& g = graded[i];
    try {
      g.result = grade_problem(*chosen[i], built[i], run_dir, options, account, second_runner, g.protections, g.started);
    } catch (const std::exception& e) {
      BuiltRunner broken = built[i];
      broken.ok = false;
      broken.error = std::string("the grader could not run this problem: ") + e.what();
      broken.fault = Fault::grader;
      g.result = not_built(*chosen[i], broken);
    }
  });
  return graded;
}

// Why the code graded would run with this grader's rights here, in words for the report; empty
// where the sandbox holds whole. `missing` names what the sandbox lacks when it is incomplete.
std::string unprotected_reason(const GraderOptions& options, const Account& account, std::string& missing) {
  if (!options.isolate) return "the sandbox is off (--no-isolation)";
  if (sandbox_complete(account, missing)) return "";
  return "the sandbox is incomplete here (missing: " + missing + ")";
}

// The sandbox must hold whole before anyone's code is compiled or run: where it cannot (no
// namespaces), the code graded would run with the grader's rights, next to other students'
// files and grades. Only an explicit --unprotected grades there, and every report says so
// (`unprotected`, set here). False, said, where the grader refuses.
bool may_grade_here(const GraderOptions& options, const Account& account, const char* program,
                    std::string& unprotected) {
  std::string missing;
  unprotected = unprotected_reason(options, account, missing);
  if (missing.empty() || options.allow_unprotected || options.check_sandbox) return true;
  std::cerr << program << ": refused: the sandbox cannot be built here (missing: " << missing
            << "), so the code graded would run with this grader's rights. Grade your own files with "
               "--unprotected (scripts/grade does); grade others' only where the sandbox holds (docs/grader.md)\n";
  return false;
}

// --check-sandbox: what holds here, the sandbox and each of the grading's groups; 0 if whole.
int print_sandbox_check(const GradingGroups& groups, const std::string& unprotected) {
  std::cout << (unprotected.empty() ? "sandbox: complete" : "sandbox: " + unprotected) << "\n"
            << "cpu share: "
            << (groups.cpu.empty() ? "no writable cgroup here: each test's limit counts the runner's CPU time"
                                   : "a group per grading, " + groups.cpu)
            << "\nmemory budget: "
            << (groups.memory.empty() ? "no writable memory cgroup here: each program's address space is capped"
                                      : "a group per grading, " + groups.memory)
            << "\nprocess budget: "
            << (groups.pids.empty() ? "no writable pids cgroup here: each program's account limits its processes"
                                    : "a group per grading, " + groups.pids)
            << "\n";
  return unprotected.empty() ? 0 : kExitUnprotected;
}

// A seed for this grading's random inputs, 1 to 10^9 (short enough to type after --seed).
std::uint64_t drawn_seed() {
  std::random_device device;
  return (static_cast<std::uint64_t>(device()) << 20 ^ device()) % 1000000000ull + 1;
}

// The problems of `suite` that --problem chose (all without it), in the suite's order.
std::vector<const Problem*> chosen_problems(const std::vector<Problem>& suite, const std::string& only) {
  std::vector<const Problem*> chosen;
  for (const Problem& problem : suite)
    if (only.empty() || problem.key == only) chosen.push_back(&problem);
  return chosen;
}

// One line per exercise file: built, reused from the cache, or not built.
void print_built(const std::vector<const Problem*>& chosen, const std::vector<BuiltRunner>& built) {
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    std::cerr << "  exercises/" << file_of(chosen[i]->key) << ": "
              << (!built[i].ok ? "not built (the report says why)"
                  : built[i].cached ? "unchanged since it was last built by this grader: its runner is reused"
                                    : "compiled")
              << "\n";
  }
}

// The grades in the report's order, and the protections the report states: the first problem's
// whose runner started.
struct Grades {
  std::vector<ProblemResult> results;
  Protections protections;
  bool started = false;
};

Grades in_report_order(std::vector<Graded>& graded) {
  Grades out;
  for (Graded& g : graded) {
    out.results.push_back(std::move(g.result));
    if (g.started && !out.started) out.protections = g.protections;
    out.started |= g.started;
  }
  return out;
}

// Grades `chosen` with their runners in a folder of /tmp made for this grading, removed after
// with every process of the grading's account. False, said, if the folder cannot be made.
bool grade_in_run_folder(const std::vector<const Problem*>& chosen, const std::vector<BuiltRunner>& built,
                         const GraderOptions& options, const Account& account, Grades& grades) {
  std::unique_ptr<TemporaryFolder> run_folder;
  try {
    run_folder = std::make_unique<TemporaryFolder>("/tmp/opspace-runners-");
  } catch (const std::exception& e) {
    std::cerr << "hw2-grade: " << e.what() << "\n";
    return false;
  }
  const std::string run_dir = run_folder->path();
  chmod(run_dir.c_str(), 0755);
  const unsigned jobs = options.jobs > 0 ? options.jobs : jobs_by_default(options.isolate && account.uid != 0);
  if (jobs > 1 && chosen.size() > 1)
    std::cerr << "grading " << std::min<std::size_t>(jobs, chosen.size()) << " problems at a time\n";
  std::vector<Graded> graded = grade_all(chosen, built, run_dir, options, account, jobs);
  grades = in_report_order(graded);
  run_folder.reset();
  kill_account(account);
  return true;
}

// The lines under the report: the times, the seed that replays the inputs, and what of the
// sandbox did not hold.
void print_footer(const GraderOptions& options, const Grades& grades, double build_seconds, double grading_seconds) {
  std::printf("Built in %.1f s, graded in %.1f s (seed %llu: --seed %llu replays these inputs)\n", build_seconds,
              grading_seconds, static_cast<unsigned long long>(options.seed),
              static_cast<unsigned long long>(options.seed));
  if (!options.isolate) {
    std::printf("Sandbox: off (--no-isolation)\n");
  } else if (grades.started && !grades.protections.missing().empty()) {
    std::printf("Sandbox: these protections were not available here: %s (docs/grader.md)\n",
                grades.protections.missing().c_str());
  }
  std::fflush(stdout);
}

// The files the options ask for: results.json (--gradescope, --prairielearn), JUnit XML (--junit), the report's
// page (--html). False if one could not be written.
bool write_results_files(const GraderOptions& options, const std::vector<ProblemResult>& results, double seconds,
                         bool unprotected) {
  bool written = true;
  if (!options.gradescope_path.empty()) {
    written &= write_file(options.gradescope_path, "results.json",
                          [&](std::ostream& out) {
                            write_gradescope(out, results, seconds,
                                             {options.hidden, options.hidden_as, options.seed, options.gradescope_format,
                                              unprotected});
                          });
  }
  if (!options.prairielearn_path.empty()) {
    written &= write_file(options.prairielearn_path, "PrairieLearn's results.json", [&](std::ostream& out) {
      write_prairielearn(out, results, seconds, {options.hidden, options.seed});
    });
  }
  if (!options.junit_path.empty()) {
    written &= write_file(options.junit_path, "JUnit XML", [&](std::ostream& out) { write_junit(out, results, seconds); });
  }
  if (!options.html_path.empty()) {
    std::error_code ec;  // a folder that cannot be made: write_file says the page cannot be written
    fs::create_directories(fs::path(options.html_path).parent_path(), ec);
    const bool page = write_file(options.html_path, "the report's page", [&](std::ostream& out) {
      write_html_report(out, results, options.hidden, options.seed);
    });
    if (page) std::cout << "open " << shown_path(options.html_path) << "\n";
    written &= page;
  }
  return written;
}

}  // namespace

int grader_main(int argc, char** argv, const std::string& default_exercises) {
  GraderOptions options;
  options.exercises = default_exercises;
  options.timeout = kDefaultTimeout;
  int exit_code = 0;
  if (!parse_grader_options(argc, argv, options, exit_code)) return exit_code;
  if (!options.isolate && geteuid() == 0) {
    std::cerr << argv[0] << ": --no-isolation would run a student's code as root: refused\n";
    return 2;
  }
  become_subreaper();
  clean_up_when_interrupted();
  // Before any child: the gradings running at once then share the machine by group
  // (grading_group.hpp).
  const GradingGroups groups = options.isolate ? join_grading_groups(grading_budget(options)) : GradingGroups{};
  Account account;
  try {
    account = options.isolate ? grading_account(options.user) : Account{};
  } catch (const std::exception& e) {
    std::cerr << argv[0] << ": " << e.what() << "\n";
    return 2;
  }
  std::string unprotected;
  if (!may_grade_here(options, account, argv[0], unprotected)) return kExitUnprotected;
  if (options.check_sandbox) return print_sandbox_check(groups, unprotected);
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
  const auto start = std::chrono::steady_clock::now();
  std::cerr << "building the runners of " << chosen.size() << " problem(s)...\n";
  const BuildSettings settings{cache_dir, account, options.isolate, 180.0};
  const std::vector<BuiltRunner> built = build_all(chosen, toolchain, options, settings);
  const double build_seconds = since(start);
  print_built(chosen, built);

  const auto grading_start = std::chrono::steady_clock::now();
  Grades grades;
  if (!grade_in_run_folder(chosen, built, options, account, grades)) return 1;
  std::cerr << prune_runner_cache(cache_dir, options.cache_mib << 20).line(options.cache_mib << 20) << "\n";
  const double grading_seconds = since(grading_start), seconds = since(start);
  print_report(std::cout, grades.results, options.hidden, options.seed);
  print_footer(options, grades, build_seconds, grading_seconds);
  return write_results_files(options, grades.results, seconds, !unprotected.empty()) ? 0 : 1;
}

}  // namespace opspace::grading
