/// @file runner_process.hpp
/// The grader's handle on one problem's runner: it starts the runner in the sandbox, sends
/// requests and reads answers under the test's deadline, collects what the student's code
/// prints, and restarts the runner for the next test after a crash, a time-out, an exit or a
/// malformed answer. Everything read from the runner is checked before it is used.
#pragma once

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/fault.hpp"
#include "protocol/protocol.hpp"
#include "sandbox/sandbox.hpp"

namespace opspace::grading {

/// The runner cannot answer any more in this test: it crashed, exited, ran out of time or
/// sent something malformed. what() says which, in words for the student.
class RunnerFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The student's function threw; what() is "your code threw an exception: <its text>",
/// the text cut short and stripped of control characters.
class StudentException : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// How to start a runner.
struct RunnerConfig {
  std::string binary;    ///< absolute path of the runner program
  std::string work_dir;  ///< the folder it runs in (read-only), holding the binary and nothing else
  Account account;       ///< when the grader is root: the unprivileged account it runs as
  bool isolate = true;   ///< the sandbox's namespaces, limits and filter (sandbox.hpp)
  std::vector<std::string> env;  ///< its environment (empty, or the sanitizers' options)
  std::vector<std::string> runtime;  ///< the files it needs to start (elf_files.hpp)
};

/// What the student's code printed during one test: the first bytes and the total count.
struct Printed {
  std::string text;        ///< at most kMaxPrinted bytes, as printed
  std::size_t total = 0;   ///< how many bytes were printed in all
};

/// One problem's runner, started on the first request.
class RunnerProcess {
 public:
  static constexpr std::size_t kMaxPrinted = 2000;  ///< bytes of prints kept per test

  explicit RunnerProcess(RunnerConfig config);
  ~RunnerProcess();
  RunnerProcess(const RunnerProcess&) = delete;
  RunnerProcess& operator=(const RunnerProcess&) = delete;

  /// How many times the test's limit a runner may keep the grader waiting, computing or not:
  /// the limit itself counts the runner's CPU time, so that a machine kept busy by others
  /// (another grading, another student's processes) does not make an honest runner late.
  static constexpr double kWaitFactor = 5.0;

  /// Starts a test and gives it a clean slate (no failure, no prints). The runner may spend
  /// `timeout_seconds` of CPU time on the test, and keep the grader waiting until `deadline`
  /// plus (kWaitFactor - 1) times that limit.
  void begin_test(std::chrono::steady_clock::time_point deadline, double timeout_seconds);
  /// Ends a test: kills the runner if it failed (the next test starts a new one); returns
  /// what the student's code printed during it.
  Printed end_test();
  /// The failure of the current test, or empty.
  const std::string& failure() const { return failure_; }
  /// Who caused each test's failure, one per end_test() in order (Fault::none: it did not fail).
  /// Kept here, where it is known, since a test's result keeps the failure's text alone.
  const std::vector<Fault>& test_faults() const { return test_faults_; }
  /// How many requests the current test has sent (begin_test counts from 0).
  long calls_in_test() const { return calls_in_test_; }
  /// What a run made on another runner of the same binary printed, and the failure that ended
  /// it (if any), taken as if both had happened here in the current test (runs_ahead.hpp): the
  /// prints are appended, and the failure, unless one came first, ends this runner at end_test().
  void take_run(const Printed& printed, const std::string& failure, Fault fault);

  /// Sends `arguments` to `function` and returns the value's bytes, exactly `value_size` of
  /// them. Throws RunnerFailure or StudentException.
  std::vector<unsigned char> call(protocol::Function function, const std::vector<unsigned char>& arguments,
                                  std::size_t value_size);

  /// Sets the runner's process aside, untouched, and gives the calls that follow a fresh one
  /// (started on the first call) with the current test's whole limit, until
  /// end_fresh_process(), which ends it and takes back the one set aside: a simulated run's
  /// process then knows no call before its own first tick, whichever runner makes the run
  /// (runs_ahead.hpp). Its prints and failure are the current test's, as any call's.
  void begin_fresh_process();
  void end_fresh_process();

  /// Kills the runner and everything it started.
  void stop();
  /// The protections of the last start (sandbox.hpp).
  const Protections& protections() const { return protections_; }
  /// How many times a runner was started.
  int starts() const { return starts_; }

 private:
  void start();
  [[noreturn]] void fail(const std::string& what, Fault fault = Fault::submission);
  // Reads exactly `size` bytes of the answer into `out`, draining the prints meanwhile.
  void read_answer(void* out, std::size_t size);
  void drain_prints(int fd_ready);
  std::string ended_how();

  // One process of the runner and where the current test stands with it: what
  // begin_fresh_process() sets aside.
  struct Process {
    Sandboxed program;
    bool running = false;
    int request_fd = -1, answer_fd = -1, print_fd = -1;
    std::uint32_t sequence = 0;  // its requests' numbers, from 1 in each process
    std::vector<unsigned char> inbox;
    std::size_t inbox_begin = 0, inbox_end = 0;
    std::chrono::steady_clock::time_point deadline;
    double timeout_seconds = 0.0, cpu_at_begin = 0.0;
    unsigned long long memory_kills = 0;
    std::chrono::steady_clock::time_point set_aside;  // when begin_fresh_process() took it
  };
  void swap_process(Process& other);

  RunnerConfig config_;
  Sandboxed program_;
  bool running_ = false;
  int request_fd_ = -1, answer_fd_ = -1, print_fd_ = -1;
  std::uint32_t sequence_ = 0;
  std::vector<Process> set_aside_;  // the processes of begin_fresh_process(), innermost last
  // The runner's CPU time in seconds (its threads and the children it reaped), from /proc.
  double cpu_seconds() const;
  std::chrono::steady_clock::time_point deadline_;
  double timeout_seconds_ = 0.0;
  double cpu_at_begin_ = 0.0;  // the runner's CPU time when the test began (0: started since)
  std::chrono::steady_clock::time_point last_cpu_check_;
  std::string failure_;
  Fault fault_ = Fault::none;
  std::vector<Fault> test_faults_;
  Printed printed_;
  long calls_in_test_ = 0;
  // What was read from the answer pipe and not yet taken (read_answer): one read takes an
  // answer's header and payload together. Emptied when the runner stops.
  std::vector<unsigned char> inbox_;
  std::size_t inbox_begin_ = 0, inbox_end_ = 0;
  std::vector<unsigned char> outbox_;  // the request being sent, its memory reused from tick to tick
  Protections protections_;
  int starts_ = 0;
  unsigned long long memory_kills_ = 0;  ///< the grading's count when it started (grading_group.hpp)
};

}  // namespace opspace::grading
