// The runs a second runner makes ahead (grader/trusted/runs_ahead.hpp), without processes: the
// functions are none (no run here calls one), so the RunnerProcess standing for the second runner
// is never started; each run records which thread made it.
#include <doctest/doctest.h>

#include <atomic>
#include <thread>

#include "diagnosis.hpp"
#include "pinned_run.hpp"
#include "runner_process.hpp"
#include "runs_ahead.hpp"

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

}  // namespace opspace::grading
