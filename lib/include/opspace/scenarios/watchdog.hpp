/// @file scenarios/watchdog.hpp
/// Stops a program whose closed-loop run makes no progress: a controller caught in an endless
/// loop never returns, so nothing inside the loop can notice. A thread watches the time of the
/// last step instead, and ends the program with a message saying what hung and where.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace opspace::scenarios {

/// Exit code of a program stopped by a Watchdog (that of timeout(1)).
inline constexpr int kWatchdogExitCode = 124;

/// Watches one run. Unless beat() is called at least every `seconds` of wall time, it prints
///   "<what>: no progress for <seconds> s of wall time at t = <last beat> s ..."
/// on stderr and ends the program with kWatchdogExitCode (std::_Exit: the run's log is left
/// as it was). The thread runs from construction to destruction; with seconds <= 0 there is
/// no thread and the watchdog does nothing.
class Watchdog {
 public:
  /// `what` names the run in the message, e.g. "problem 1b, PART3".
  Watchdog(double seconds, std::string what);
  ~Watchdog();
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

  /// The run reached simulated time t: the clock starts again. Lock-free, no allocation.
  void beat(double t) noexcept;

 private:
  void watch();

  double seconds_;
  std::string what_;
  std::atomic<std::chrono::steady_clock::rep> last_beat_;  // steady_clock ticks
  std::atomic<double> t_{0.0};
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;
};

/// The watchdog's seconds from the environment variable OPSPACE_WATCHDOG (scripts/run sets it,
/// 10 s by default): 0 when it is unset or empty (no watchdog). Throws std::invalid_argument
/// naming the variable unless it is a number of seconds >= 0.
double watchdog_seconds_from_environment();

}  // namespace opspace::scenarios
