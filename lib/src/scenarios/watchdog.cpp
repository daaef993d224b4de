#include "opspace/scenarios/watchdog.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace opspace::scenarios {

namespace {

std::chrono::steady_clock::rep now() { return std::chrono::steady_clock::now().time_since_epoch().count(); }

}  // namespace

Watchdog::Watchdog(double seconds, std::string what)
    : seconds_(seconds), what_(std::move(what)), last_beat_(now()) {
  if (seconds_ > 0.0) thread_ = std::thread([this] { watch(); });
}

Watchdog::~Watchdog() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void Watchdog::beat(double t) noexcept {
  t_.store(t, std::memory_order_relaxed);
  last_beat_.store(now(), std::memory_order_release);
}

void Watchdog::watch() {
  using std::chrono::duration;
  using std::chrono::steady_clock;
  // Look a few times per period: the program stops at most a quarter period late.
  const auto poll = std::chrono::duration_cast<steady_clock::duration>(duration<double>(std::min(seconds_ / 4, 0.25)));
  const auto limit = std::chrono::duration_cast<steady_clock::duration>(duration<double>(seconds_));
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, poll, [this] { return stop_; })) {
    const steady_clock::duration idle(now() - last_beat_.load(std::memory_order_acquire));
    if (idle < limit) continue;
    // The main thread is stuck (in the controller, most likely): C stdio is thread-safe, so
    // flush what the program printed so far, say what happened, and stop.
    std::fflush(stdout);
    std::fprintf(stderr,
                 "\n%s: no progress for %g s of wall time at t = %.3f s: the controller (or the "
                 "simulation step) has not returned. An endless loop? The program is stopped.\n"
                 "(scripts/run --watchdog SECONDS or OPSPACE_WATCHDOG=SECONDS changes the limit; "
                 "0 turns it off, e.g. to step through your code in a debugger.)\n",
                 what_.c_str(), seconds_, t_.load(std::memory_order_relaxed));
    std::fflush(stderr);
    std::_Exit(kWatchdogExitCode);
  }
}

double watchdog_seconds_from_environment() {
  const char* text = std::getenv("OPSPACE_WATCHDOG");
  if (text == nullptr || *text == '\0') return 0.0;
  char* end = nullptr;
  const double seconds = std::strtod(text, &end);
  if (*end != '\0' || !(seconds >= 0.0)) {
    throw std::invalid_argument(std::string("OPSPACE_WATCHDOG='") + text +
                                "': expected a number of seconds >= 0 (0: no watchdog)");
  }
  return seconds;
}

}  // namespace opspace::scenarios
