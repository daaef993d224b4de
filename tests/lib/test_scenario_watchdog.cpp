// The watchdog of the closed-loop runs (scenarios/watchdog.hpp): a controller that never
// returns ends the program with a message naming the problem and part; a run that makes
// progress is left alone. The hanging run is a child process (it ends with _Exit).
#include <doctest/doctest.h>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <string>
#include <thread>

#include "opspace/scenarios/common.hpp"
#include <problems/1b/run/scenario.hpp>
#include "opspace/scenarios/watchdog.hpp"

using namespace opspace;
namespace p1b = opspace::scenarios::p1b;

namespace {

// Gravity compensation (a harmless torque) for 50 ms, then an endless loop, as a student's
// controller caught in a while loop whose condition never changes.
p1b::Vector6d hangs_after_50_ms(hw2::p1b::Part, const hw2::p1b::State& s, const hw2::p1b::Goal&) {
  if (s.t >= 0.05 - 1e-9) {
    for (;;) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return s.g;
}

p1b::Vector6d gravity(hw2::p1b::Part, const hw2::p1b::State& s, const hw2::p1b::Goal&) { return s.g; }

struct Child {
  int status = -1;      ///< waitpid status, -1 if it had to be killed
  std::string stderr_;  ///< what it wrote on stderr
};

// Runs `body` in a child process whose stderr is captured; kills it after `limit` seconds.
template <class Body>
Child run_in_child(Body body, double limit) {
  int pipe_fd[2];
  REQUIRE(pipe(pipe_fd) == 0);
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    close(pipe_fd[0]);
    dup2(pipe_fd[1], STDERR_FILENO);
    body();
    _exit(0);
  }
  close(pipe_fd[1]);
  Child child;
  const auto start = std::chrono::steady_clock::now();
  bool open = true, running = true;
  while (open || running) {
    if (std::chrono::steady_clock::now() - start > std::chrono::duration<double>(limit)) {
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
      child.status = -1;
      break;
    }
    pollfd fd{pipe_fd[0], POLLIN, 0};
    if (open && poll(&fd, 1, 20) > 0) {
      char buffer[4096];
      const ssize_t n = read(pipe_fd[0], buffer, sizeof buffer);
      if (n > 0) child.stderr_.append(buffer, static_cast<std::size_t>(n));
      if (n <= 0) open = false;
    } else if (!open) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (running && waitpid(pid, &child.status, WNOHANG) == pid) running = false;
  }
  close(pipe_fd[0]);
  return child;
}

}  // namespace

TEST_CASE("a controller that never returns is stopped by the watchdog, which names the problem, part and time") {
  scenarios::RunOptions options;
  options.duration = 1.0;
  options.watchdog = 0.5;
  const auto start = std::chrono::steady_clock::now();
  // 60 s only guards the suite against a watchdog that never fires.
  const Child child = run_in_child(
      [&] { p1b::run(hw2::p1b::Part::kDynamicallyConsistentNullspace, &hangs_after_50_ms, options); }, 60.0);
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  INFO("stderr of the run: " << child.stderr_);
  REQUIRE(child.status != -1);
  REQUIRE(WIFEXITED(child.status));
  CHECK(WEXITSTATUS(child.status) == scenarios::kWatchdogExitCode);
  CHECK(child.stderr_.find("problem 1b, PART3") != std::string::npos);
  CHECK(child.stderr_.find("no progress for 0.5 s of wall time at t = 0.050 s") != std::string::npos);
  CHECK(child.stderr_.find("OPSPACE_WATCHDOG") != std::string::npos);
  // It waited for the limit: never earlier than 0.5 s of silence.
  CHECK(waited >= 0.5);
}

TEST_CASE("a run that makes progress reaches its end under a watchdog far shorter than the run") {
  scenarios::RunOptions options;
  options.duration = 8.0;  // 8000 steps: about 0.8 s of wall time in a release build, longer
  options.watchdog = 0.5;  // than the watchdog's limit, but each step takes a tenth of a ms
  const Child child = run_in_child(
      [&] {
        const p1b::Result r = p1b::run(hw2::p1b::Part::kTipPd, &gravity, options);
        _exit(r.failure.empty() && r.samples.size() == 8001 ? 0 : 3);
      },
      60.0);
  INFO("stderr of the run: " << child.stderr_);
  REQUIRE(child.status != -1);
  REQUIRE(WIFEXITED(child.status));
  CHECK(WEXITSTATUS(child.status) == 0);
  CHECK(child.stderr_.empty());
}

TEST_CASE("OPSPACE_WATCHDOG sets the watchdog's seconds: unset or empty is none, anything but seconds >= 0 is an error") {
  unsetenv("OPSPACE_WATCHDOG");
  CHECK(scenarios::watchdog_seconds_from_environment() == 0.0);
  setenv("OPSPACE_WATCHDOG", "", 1);
  CHECK(scenarios::watchdog_seconds_from_environment() == 0.0);
  setenv("OPSPACE_WATCHDOG", "2.5", 1);
  CHECK(scenarios::watchdog_seconds_from_environment() == 2.5);
  for (const char* bad : {"ten", "-1", "5s", "nan"}) {
    setenv("OPSPACE_WATCHDOG", bad, 1);
    CHECK_THROWS_WITH_AS(scenarios::watchdog_seconds_from_environment(),
                         doctest::Contains("OPSPACE_WATCHDOG"), std::invalid_argument);
  }
  unsetenv("OPSPACE_WATCHDOG");
}
