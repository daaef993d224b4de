// The runs a second runner makes ahead (grader/trusted/run/runs_ahead.hpp). First without processes:
// the functions are none (no run here calls one), so the RunnerProcess standing for the second
// runner is never started; each run records which thread made it. Then with runners that say
// what their process has answered (tests/grader/fake_runner.cpp, "history", unsandboxed): the
// process a run is made in, by a test or ahead.
#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "run/recording.hpp"
#include "pinned_run.hpp"
#include "run/remote_api.hpp"
#include "run/runner_process.hpp"
#include "run/runs_ahead.hpp"

namespace opspace::grading {
namespace {

struct Made {
  std::thread::id by;  // the thread that made the run
};

std::atomic<int> g_made{0};

const PinnedRun<Made>& made_run(const Hw2Api& api, int variant) {
  return pinned_run<Made>(api.identity, variant, 1e-6, [](LawPin&) {
    ++g_made;
    return Made{std::this_thread::get_id()};
  });
}

ListedRun listed(int variant) {
  return {[variant](std::uint64_t identity) { return run_key<Made>(identity, variant); },
          [variant](const Hw2Api& api) { made_run(api, variant); }};
}

Hw2Api api_of(std::uint64_t identity) {
  Hw2Api api;
  api.identity = identity;
  return api;
}

RunnerConfig nowhere() { return RunnerConfig{"/nonexistent/runner", "/nonexistent", Account{}, false, {}, {}}; }

RunnerConfig history() { return RunnerConfig{OPSPACE_FAKE_RUNNER, "/", Account{}, false, {"OPSPACE_FAKE_RUNNER=history"}, {}}; }

// What a call's process had seen, the call included: how many calls it answered, and this
// call's number (fake_runner's "history", through p1a's mass_matrix).
struct Seen {
  double calls = 0, number = 0;
};
Seen seen(const Hw2Api& api) {
  const Eigen::Matrix2d m = api.p1a.mass_matrix(1.0, 2.0);
  return {m(0, 0), m(1, 0)};
}

// A run of two ticks that keeps what its first tick's process had seen.
const PinnedRun<Seen>& history_run(const Hw2Api& api, int variant) {
  return pinned_run<Seen>(api.identity, variant, 1e-6, [&api](LawPin&) {
    const Seen first = seen(api);
    seen(api);
    return first;
  });
}

ListedRun listed_history(int variant) {
  return {[variant](std::uint64_t identity) { return run_key<Seen>(identity, variant); },
          [variant](const Hw2Api& api) { history_run(api, variant); }};
}

constexpr double kLimit = 30.0;  // seconds: far more than a few calls to a local process take

void begin(RunnerProcess& runner) {
  runner.begin_test(std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                         std::chrono::duration<double>(kLimit)),
                    kLimit);
}

}  // namespace

TEST_CASE("a run made ahead is given to the first test that asks, which waits for it, and read by the next") {
  RunnerProcess second(nowhere());
  const Hw2Api api = api_of(5001);
  const int before = g_made;
  RunsAhead ahead({listed(1)}, api, second, 30.0);
  Recording recording;
  {
    TestInProgress test(nullptr, &recording);
    const PinnedRun<Made>& run = made_run(api, 1);
    CHECK(run.result.by != std::this_thread::get_id());  // made by the second runner's thread
    CHECK(test.given);
  }
  TestInProgress next(nullptr, &recording);
  CHECK(&made_run(api, 1) == &made_run(api, 1));
  CHECK_FALSE(next.given);  // read, not given: the first test took its records
  CHECK(g_made - before == 1);
}

TEST_CASE("a test that has taken a run, or runs outside a test, makes a run made ahead again itself") {
  RunnerProcess second(nowhere());
  const Hw2Api api = api_of(5002);
  const int before = g_made;
  RunsAhead ahead({listed(1), listed(2), listed(3)}, api, second, 30.0);
  {
    TestInProgress test(nullptr, nullptr);
    CHECK(made_run(api, 1).result.by != std::this_thread::get_id());
    // Its records would follow the first run's: made here, as this test would have made it.
    CHECK(made_run(api, 2).result.by == std::this_thread::get_id());
  }
  CHECK(made_run(api, 3).result.by == std::this_thread::get_id());
  CHECK(g_made - before == 5);  // three made ahead, two of them again here
}

TEST_CASE("the second runner's share is the list's odd positions, whatever the timing") {
  const std::vector<ListedRun> share = second_runner_share({listed(10), listed(11), listed(12), listed(13)});
  REQUIRE(share.size() == 2);
  CHECK(share[0].key(7) == run_key<Made>(7, 11));
  CHECK(share[1].key(7) == run_key<Made>(7, 13));
}

// Issue 58: a runner's process that answered other calls first could answer a run differently
// (a `static` in the student's code): whoever makes a run, its process answers nothing before
// the run's first tick. Seen to fail before: the runs' first calls were the process's 4th and 6th
// (after the test's own three, then the first run's two) and, made ahead, the second runner's 1st
// and 3rd.
TEST_CASE("a run a test makes is made in a process of its own, and the test's runner keeps its process") {
  RunnerProcess runner(history());
  const Hw2Api api = remote_api("1a", runner);
  begin(runner);
  {
    TestInProgress test(&runner, nullptr);
    for (int call = 1; call <= 3; ++call) CHECK(seen(api).calls == call);  // as a law test's
    for (int variant : {1, 2}) {
      const Seen first = history_run(api, variant).result;
      CHECK(first.calls == 1);
      CHECK(first.number == 1);  // nor does the call's number tell
    }
    // The test's own process is the one before the runs, with its own calls only.
    const Seen after = seen(api);
    CHECK(after.calls == 4);
    CHECK(after.number == 4);
  }
  runner.end_test();
  CHECK(runner.failure().empty());
  CHECK(runner.starts() == 3);
}

TEST_CASE("a second runner makes each run in a process of its own, as a test would") {
  RunnerProcess runner(history()), second(history());
  const Hw2Api api = remote_api("1a", runner);
  Hw2Api second_api = remote_api("1a", second);
  second_api.identity = api.identity;
  {
    RunsAhead ahead({listed_history(1), listed_history(2)}, second_api, second, kLimit);
    for (int variant : {1, 2}) {
      begin(runner);
      TestInProgress test(&runner, nullptr);
      const Seen first = history_run(api, variant).result;
      CHECK(test.given);
      CHECK(first.calls == 1);
      CHECK(first.number == 1);
      runner.end_test();
    }
  }
  CHECK(second.starts() == 2);
  CHECK(runner.starts() == 0);
}

}  // namespace opspace::grading
