// A controller caught in an endless loop, live: nothing inside the loop can notice, so the
// watchdog's thread ends the program with a message naming the hang (lib/src/live/run.cpp,
// scenarios/watchdog.hpp). Run in a child process, which the watchdog ends.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <sstream>
#include <string>
#include <thread>

#include <problems/1b/contract.hpp>
#include <problems/1b/run/lab.hpp>
#include "opspace/live/run.hpp"
#include "opspace/scenarios/watchdog.hpp"

using namespace opspace;
using hw2::p1b::Part;

TEST_CASE("a controller that never returns ends the live program with the watchdog's message") {
  int err[2];
  REQUIRE(pipe(err) == 0);
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    dup2(err[1], STDERR_FILENO);
    close(err[0]);
    live::P1bLab lab("hw2-p1", Part::kDynamicallyConsistentNullspace,
                     [](Part part, const hw2::p1b::State& s, const hw2::p1b::Goal& g) {
                       if (s.t >= 0.05) {
                         static std::atomic<bool> forever{true};
                         while (forever) std::this_thread::sleep_for(std::chrono::milliseconds(10));
                       }
                       return hw2::p1b::control(part, s, g);
                     });
    live::LiveOptions options;
    options.watchdog = 0.5;
    options.duration = 5.0;
    options.wait_for_page = false;  // no page here: the run starts at once
    std::ostringstream out;
    live::serve(lab, options, out);
    std::_Exit(0);  // the watchdog did not stop it
  }
  close(err[1]);
  std::string message;
  char buffer[512];
  for (ssize_t n; (n = read(err[0], buffer, sizeof buffer)) > 0;) message.append(buffer, static_cast<std::size_t>(n));
  close(err[0]);
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  CHECK_MESSAGE(WEXITSTATUS(status) == scenarios::kWatchdogExitCode, message);
  CHECK_MESSAGE(message.find("hw2-p1 --live, the controller: no progress") != std::string::npos, message);
}
