#include "run/runs_ahead.hpp"

#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include "run/recording.hpp"
#include "run/runner_process.hpp"

namespace opspace::grading {

namespace {

// A run, once made (or reserved for the second runner). What a run made ahead recorded waits
// here for the test it is given to.
struct Slot {
  bool ready = false;
  bool ahead = false;               // made (or to be made) on the second runner, not yet given
  std::shared_ptr<const void> run;  // the PinnedRun; null if a run made ahead was not made
  Recording recording;              // its calls, as a test that made it first records them
  Printed printed;                  // what the code printed during it
  std::string failure;              // the runner's failure during it, if any
  Fault fault = Fault::none;
};

std::mutex g_mutex;
std::condition_variable g_ready;
std::map<RunKey, std::shared_ptr<Slot>> g_slots;

// The run this thread makes ahead (RunsAhead::make_all), kept here until its test ends.
struct MakingAhead {
  RunKey key;
  std::shared_ptr<const void> made;
};
thread_local MakingAhead* t_ahead = nullptr;
thread_local TestInProgress* t_test = nullptr;

// A test that has neither called its runner nor been given a run: its calls, prints and failure
// so far are none, so a run's records become its own exactly as if it had made the run.
bool fresh(const TestInProgress* test) {
  return test != nullptr && !test->given && (test->runner == nullptr || test->runner->calls_in_test() == 0);
}

// The calls of a run made in a test go to a fresh process of the test's runner, from the run's
// first tick to its end, as a run made ahead goes to a second runner started for it: whoever
// makes a run, its process has answered no call before (issue 58). No call, no process started.
class FreshProcess {
 public:
  explicit FreshProcess(TestInProgress* test) : runner_(test ? test->runner : nullptr) {
    if (runner_) runner_->begin_fresh_process();
  }
  ~FreshProcess() {
    if (runner_) runner_->end_fresh_process();
  }
  FreshProcess(const FreshProcess&) = delete;
  FreshProcess& operator=(const FreshProcess&) = delete;

 private:
  RunnerProcess* runner_;
};

void give(Slot& slot, TestInProgress& test) {
  if (test.recording) *test.recording = std::move(slot.recording);
  if (test.runner) test.runner->take_run(slot.printed, slot.failure, slot.fault);
  test.given = true;
  slot.ahead = false;
}

}  // namespace

const void* shared_run(const RunKey& key, const std::function<std::shared_ptr<const void>()>& make) {
  if (t_ahead) {
    // The second runner's thread makes its own run only (a listed run asks for one run).
    if (!(t_ahead->key == key)) throw std::logic_error("a listed run asked for a run it does not list");
    t_ahead->made = make();
    return t_ahead->made.get();
  }
  std::unique_lock<std::mutex> lock(g_mutex);
  for (auto it = g_slots.find(key); it != g_slots.end(); it = g_slots.find(key)) {
    const std::shared_ptr<Slot> slot = it->second;
    g_ready.wait(lock, [&slot] { return slot->ready; });
    const auto now = g_slots.find(key);
    if (now == g_slots.end() || now->second != slot) continue;  // its maker threw: look again
    if (!slot->ahead) return slot->run.get();
    // Made ahead: this test's, as if it had made it; a grader's failure to start the second
    // runner is no one's to take (the run is made again on the test's own runner).
    if (slot->run && slot->fault != Fault::grader && fresh(t_test)) {
      give(*slot, *t_test);
      return slot->run.get();
    }
    g_slots.erase(now);  // this test could not have made it so: it makes it, as it would have
    break;
  }
  const auto slot = std::make_shared<Slot>();
  g_slots[key] = slot;
  lock.unlock();
  std::shared_ptr<const void> run;
  try {
    const FreshProcess fresh_process(t_test);
    run = make();
  } catch (...) {
    lock.lock();
    if (const auto it = g_slots.find(key); it != g_slots.end() && it->second == slot) g_slots.erase(it);
    slot->ready = true;
    g_ready.notify_all();
    throw;
  }
  lock.lock();
  slot->run = run;
  slot->ready = true;
  g_ready.notify_all();
  return run.get();
}

TestInProgress::TestInProgress(RunnerProcess* runner_of_test, Recording* recording_of_test)
    : runner(runner_of_test), recording(recording_of_test) {
  t_test = this;
}

TestInProgress::~TestInProgress() { t_test = nullptr; }

std::vector<ListedRun> second_runner_share(const std::vector<ListedRun>& runs) {
  std::vector<ListedRun> share;
  for (std::size_t i = 1; i < runs.size(); i += 2) share.push_back(runs[i]);
  return share;
}

RunsAhead::RunsAhead(const std::vector<ListedRun>& runs, const Hw2Api& api, RunnerProcess& runner, double timeout)
    : api_(api), runner_(runner), timeout_(timeout) {
  std::lock_guard<std::mutex> lock(g_mutex);
  for (const ListedRun& listed : runs) {
    const RunKey key = listed.key(api.identity);
    if (g_slots.count(key) != 0) continue;  // made already
    const auto slot = std::make_shared<Slot>();
    slot->ahead = true;
    g_slots[key] = slot;
    runs_.emplace_back(key, listed.make);
  }
  try {
    thread_ = std::thread([this] { make_all(); });
  } catch (const std::system_error&) {
    // No thread: each run is made by the first test that asks for it, as with one runner.
    for (const auto& run : runs_) {
      g_slots[run.first]->ready = true;
    }
  }
}

RunsAhead::~RunsAhead() {
  if (thread_.joinable()) thread_.join();
  std::lock_guard<std::mutex> lock(g_mutex);
  for (const auto& run : runs_)
    if (const auto it = g_slots.find(run.first); it != g_slots.end() && it->second->ahead) g_slots.erase(it);
}

void RunsAhead::make_all() {
  for (const auto& [key, make] : runs_) {
    Recording recording;
    MakingAhead making{key, nullptr};
    const auto budget = std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(timeout_));
    // A process of its own for each run, as a run made by a test has (FreshProcess).
    runner_.stop();
    runner_.begin_test(std::chrono::steady_clock::now() + budget, timeout_);
    t_ahead = &making;
    try {
      make(recorded(api_, recording));
    } catch (...) {
      making.made = nullptr;  // not made as a test would take it: the test that asks makes it
    }
    t_ahead = nullptr;
    const std::string failure = runner_.failure();
    Printed printed = runner_.end_test();
    std::lock_guard<std::mutex> lock(g_mutex);
    Slot& slot = *g_slots.at(key);
    slot.run = std::move(making.made);
    slot.recording = std::move(recording);
    slot.printed = std::move(printed);
    slot.failure = failure;
    slot.fault = runner_.test_faults().empty() ? Fault::none : runner_.test_faults().back();
    slot.ready = true;
    g_ready.notify_all();
  }
}

}  // namespace opspace::grading
