/// @file runs_ahead.hpp
/// A problem's simulated runs, shared by the tests that read them (pinned_run.hpp), and made
/// ahead on a second runner when one problem is graded and a core is spare (issue 50): the
/// problem's graded code lists its runs in the order its tests first ask for them
/// (Problem::runs), a second runner of the same binary makes a fixed share of them in a thread,
/// and each is given to the first test that asks for it, in the tests' order, with what it
/// recorded (the calls the diagnosis reads, the prints, the runner's failure) as if that test
/// had made it. Every run, made ahead or by a test, is made in a process of its own whose first
/// call is the run's first tick, so that what a process has answered before each call is fixed
/// by the problem's tests, never by who makes the runs (issue 58). The report is that of one
/// runner (docs/grader.md, "A second runner").
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <thread>
#include <tuple>
#include <vector>

#include "run/api.hpp"

namespace opspace::grading {

class RunnerProcess;
struct Recording;

/// A run's key: its problem's kind (one address per Result type), the implementation
/// (Hw2Api::identity) and the variant (1b's part, 4's target).
struct RunKey {
  const void* kind = nullptr;
  std::uint64_t identity = 0;
  int variant = 0;
  bool operator<(const RunKey& o) const {
    return std::tie(kind, identity, variant) < std::tie(o.kind, o.identity, o.variant);
  }
  bool operator==(const RunKey& o) const { return kind == o.kind && identity == o.identity && variant == o.variant; }
};

/// A run a problem's graded code lists ahead of its tests: its key for an identity, and how
/// to make it (a call that asks pinned_run() for it, as its tests do).
struct ListedRun {
  std::function<RunKey(std::uint64_t identity)> key;
  std::function<void(const Hw2Api&)> make;
};

/// The run of `key`: made by `make` on first use, else the one made (waiting for it while
/// another thread makes it). A run made ahead (RunsAhead) is given to the first test that asks
/// for it as if that test had made it, when that test has not yet called its runner or been given
/// a run (otherwise its records would interleave): else it is made again here, as that test would.
/// Kept only once `make` has returned; if it throws, the next to ask makes it again.
const void* shared_run(const RunKey& key, const std::function<std::shared_ptr<const void>()>& make);

/// The test being run in this thread on `runner` (null: linked functions), recording its calls
/// in `recording` (null: none recorded): where a run made ahead is given, and whose runner makes
/// the runs the test asks for, each in a fresh process (RunnerProcess::begin_fresh_process).
/// run_tests() sets it.
class TestInProgress {
 public:
  TestInProgress(RunnerProcess* runner, Recording* recording);
  ~TestInProgress();
  TestInProgress(const TestInProgress&) = delete;
  TestInProgress& operator=(const TestInProgress&) = delete;

  RunnerProcess* runner;
  Recording* recording;
  bool given = false;  ///< a run made ahead was given to this test
};

/// The share of `runs` a second runner makes: those at odd positions of the list (1b: PART3's),
/// a fixed rule, never a matter of timing, so that who makes each run is the same every time.
std::vector<ListedRun> second_runner_share(const std::vector<ListedRun>& runs);

/// Makes `runs` on `runner` (`api` answered by it, with the identity of the tests' own api) in a
/// thread, each as a test of its own with `timeout` seconds (RunnerProcess::begin_test). Every
/// run is reserved before the thread starts: a test that asks for one waits for it.
class RunsAhead {
 public:
  RunsAhead(const std::vector<ListedRun>& runs, const Hw2Api& api, RunnerProcess& runner, double timeout);
  ~RunsAhead();  ///< waits for the thread; forgets the runs no test asked for
  RunsAhead(const RunsAhead&) = delete;
  RunsAhead& operator=(const RunsAhead&) = delete;

 private:
  void make_all();

  std::vector<std::pair<RunKey, std::function<void(const Hw2Api&)>>> runs_;
  Hw2Api api_;
  RunnerProcess& runner_;
  double timeout_;
  std::thread thread_;
};

}  // namespace opspace::grading
