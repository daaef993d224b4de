// The run and judge stages of a grading: each problem's runner started in the sandbox from its
// build, its tests run and judged (with a second runner making runs ahead where a core is
// spare), the library's answers the runner holds charged, several problems at once.
#include "judge/grade_problems.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "build/runner_builds.hpp"
#include "common/at_once.hpp"
#include "common/student_text.hpp"
#include "common/temporary_folder.hpp"
#include "judge/mistakes.hpp"
#include "run/remote_api.hpp"
#include "run/runner_process.hpp"
#include "run/runs_ahead.hpp"

namespace opspace::grading {

namespace fs = std::filesystem;

namespace {

// The runner's environment.
#if defined(__SANITIZE_ADDRESS__)
// No leak check at exit (the sandbox forbids the ptrace it needs); the address-space limit
// cannot apply under AddressSanitizer, so its own limits stop a memory flood. A fault signal
// kills the runner as it does in a release build (AddressSanitizer would report it and exit 1,
// which the grader would take for an exit() call).
const std::vector<std::string> kRunnerEnv = {
    "ASAN_OPTIONS=detect_leaks=0:hard_rss_limit_mb=1024:max_allocation_size_mb=1024:allocator_may_return_null=1:"
    "handle_segv=0:handle_sigbus=0:handle_sigfpe=0:handle_sigill=0"};
#else
const std::vector<std::string> kRunnerEnv = {};
#endif

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
// what it costs and why (build/library_answers.hpp).
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
    result.notes.push_back("not allowed in problem " + result.problem->key + ": exercises/" + exercise_file(result.problem->key) +
                           " reaches " + names + ", which computes " + oracle.what + ": " + cost +
                           " earn 0. Write it yourself (docs/grader.md)");
  }
  result.score = 0.0;
  for (const TestResult& r : result.results) result.score += r.score;
}

ProblemResult grade_problem(const Problem& problem, const BuiltRunner& built, const std::string& run_dir,
                            const GradingSettings& settings, const Account& account, bool second_runner,
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
  const RunnerConfig config{binary, folder, account, settings.isolate, kRunnerEnv, built.runtime};
  RunnerProcess runner(config);
  const Hw2Api api = remote_api(problem.key, runner);
  ProblemResult out;
  out.problem = &problem;
  const std::vector<Mistake> catalogue = mistakes(problem.key);
  const double timeout = settings.timeouts.at(problem.key);
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
                              const std::string& run_dir, const GradingSettings& settings, const Account& account) {
  std::vector<Graded> graded(chosen.size());
  // A core to spare for each problem (one problem graded, --jobs 2): a second runner each.
  const bool second_runner = settings.second_runner && settings.jobs >= 2 * chosen.size();
  at_once(chosen.size(), settings.jobs, [&](std::size_t i) {
    std::cerr << "grading problem " + chosen[i]->key + "...\n";  // one write: threads do not interleave it
    Graded& g = graded[i];
    try {
      g.result = grade_problem(*chosen[i], built[i], run_dir, settings, account, second_runner, g.protections, g.started);
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

Grades in_report_order(std::vector<Graded>& graded) {
  Grades out;
  for (Graded& g : graded) {
    out.results.push_back(std::move(g.result));
    if (g.started && !out.started) out.protections = g.protections;
    out.started |= g.started;
  }
  return out;
}

}  // namespace

bool grade_in_run_folder(const std::vector<const Problem*>& chosen, const std::vector<BuiltRunner>& built,
                         const GradingSettings& settings, const Account& account, Grades& grades) {
  std::unique_ptr<TemporaryFolder> run_folder;
  try {
    run_folder = std::make_unique<TemporaryFolder>("/tmp/opspace-runners-");
  } catch (const std::exception& e) {
    std::cerr << "hw2-grade: " << e.what() << "\n";
    return false;
  }
  const std::string run_dir = run_folder->path();
  chmod(run_dir.c_str(), 0755);
  if (settings.jobs > 1 && chosen.size() > 1)
    std::cerr << "grading " << std::min<std::size_t>(settings.jobs, chosen.size()) << " problems at a time\n";
  std::vector<Graded> graded = grade_all(chosen, built, run_dir, settings, account);
  grades = in_report_order(graded);
  run_folder.reset();
  kill_account(account);
  return true;
}

}  // namespace opspace::grading
