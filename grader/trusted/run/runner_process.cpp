#include "run/runner_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "run/answer_decoding.hpp"
#include "sandbox/grading_group.hpp"
#include "common/student_text.hpp"

namespace opspace::grading {

namespace {

// Resource limits of a runner. A runner holds a few fixed-size matrices: 1 GiB of address
// space is far more than it needs (AddressSanitizer reserves terabytes, so sanitized builds
// go without). CPU time: a problem's runner lives for all its tests; the wall-clock deadline
// of each test is the real bound, this one only stops a runaway that the deadline missed.
Limits runner_limits(double timeout_seconds) {
  Limits l;
#if !defined(__SANITIZE_ADDRESS__)
  l.address_space = address_space_within_budget(1ull << 30);
#endif
  l.cpu_seconds = static_cast<unsigned long long>(std::max(60.0, 10.0 * timeout_seconds));
  l.file_size = 1ull << 20;
  l.open_files = 16;
  // A runner needs one process, and its system-call filter refuses it a second one
  // (sandbox_seccomp.hpp); its threads count here too: 16 bound them under the grading's own
  // account, where no filter is offered as well.
  l.processes = 16;
  return l;
}

void close_fd(int& fd) {
  if (fd >= 0) close(fd);
  fd = -1;
}

std::string seconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g s", s);
  return buffer;
}

}  // namespace

RunnerProcess::RunnerProcess(RunnerConfig config)
    : config_(std::move(config)), inbox_(sizeof(protocol::Header) + protocol::kMaxPayload) {}

RunnerProcess::~RunnerProcess() {
  stop();
  while (!set_aside_.empty()) {
    swap_process(set_aside_.back());
    set_aside_.pop_back();
    stop();
  }
}

void RunnerProcess::begin_test(std::chrono::steady_clock::time_point deadline, double timeout_seconds) {
  deadline_ = deadline + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                             std::chrono::duration<double>((kWaitFactor - 1.0) * timeout_seconds));
  timeout_seconds_ = timeout_seconds;
  cpu_at_begin_ = running_ ? cpu_seconds() : 0.0;
  last_cpu_check_ = std::chrono::steady_clock::now();
  failure_.clear();
  fault_ = Fault::none;
  printed_ = Printed{};
  calls_in_test_ = 0;
}

void RunnerProcess::take_run(const Printed& printed, const std::string& failure, Fault fault) {
  printed_.text.append(printed.text, 0, kMaxPrinted - std::min(kMaxPrinted, printed_.text.size()));
  printed_.total += printed.total;
  if (!failure.empty() && failure_.empty()) {
    failure_ = failure;
    fault_ = fault;
  }
}

Printed RunnerProcess::end_test() {
  if (running_ && print_fd_ >= 0) drain_prints(print_fd_);
  if (!failure_.empty()) stop();
  test_faults_.push_back(fault_);
  Printed out = std::move(printed_);
  printed_ = Printed{};
  return out;
}

void RunnerProcess::start() {
  int request[2], answer[2], prints[2];
  if (pipe2(request, O_CLOEXEC) != 0) fail("the grader could not create a pipe", Fault::grader);
  if (pipe2(answer, O_CLOEXEC) != 0) {
    close(request[0]), close(request[1]);
    fail("the grader could not create a pipe", Fault::grader);
  }
  if (pipe2(prints, O_CLOEXEC) != 0) {
    close(request[0]), close(request[1]), close(answer[0]), close(answer[1]);
    fail("the grader could not create a pipe", Fault::grader);
  }
  SandboxSpec spec;
  spec.argv = {config_.binary};
  spec.env = config_.env;
  spec.work_dir = config_.work_dir;
  spec.account = config_.account;
  spec.runner = true;
  spec.runtime = config_.runtime;
  spec.isolate = config_.isolate;
  spec.limits = runner_limits(timeout_seconds_);
  spec.fds = {{0, open("/dev/null", O_RDONLY | O_CLOEXEC)},
              {1, prints[1]},
              {2, prints[1]},
              {protocol::kRequestFd, request[0]},
              {protocol::kAnswerFd, answer[1]}};
  try {
    program_ = spawn(spec);
  } catch (const std::exception& e) {
    for (int fd : {spec.fds[0].second, request[0], request[1], answer[0], answer[1], prints[0], prints[1]}) close(fd);
    fail(std::string("the grader could not start your code: ") + e.what(), Fault::grader);
  }
  for (int fd : {spec.fds[0].second, request[0], answer[1], prints[1]}) close(fd);
  request_fd_ = request[1];
  answer_fd_ = answer[0];
  print_fd_ = prints[0];
  fcntl(print_fd_, F_SETFL, O_NONBLOCK);
  protections_ = program_.protections;
  cpu_at_begin_ = 0.0;
  // A process's requests are numbered from 1 whatever came before it: nothing it reads tells it
  // how many calls other processes of this runner answered.
  sequence_ = 0;
  running_ = true;
  ++starts_;
  memory_kills_ = grading_memory_kills();
}

void RunnerProcess::swap_process(Process& other) {
  std::swap(program_, other.program);
  std::swap(running_, other.running);
  std::swap(request_fd_, other.request_fd);
  std::swap(answer_fd_, other.answer_fd);
  std::swap(print_fd_, other.print_fd);
  std::swap(sequence_, other.sequence);
  std::swap(inbox_, other.inbox);
  std::swap(inbox_begin_, other.inbox_begin);
  std::swap(inbox_end_, other.inbox_end);
  std::swap(deadline_, other.deadline);
  std::swap(timeout_seconds_, other.timeout_seconds);
  std::swap(cpu_at_begin_, other.cpu_at_begin);
  std::swap(memory_kills_, other.memory_kills);
}

void RunnerProcess::begin_fresh_process() {
  // What the process set aside has printed so far comes before the fresh one's prints.
  if (running_ && print_fd_ >= 0) drain_prints(print_fd_);
  Process fresh;
  fresh.inbox.resize(inbox_.size());
  const auto now = std::chrono::steady_clock::now();
  // The limit of a test's runner (begin_test): the test's limit of CPU time, counted from the
  // process's start (cpu_at_begin 0), and kWaitFactor times that of waiting.
  fresh.deadline = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                             std::chrono::duration<double>(kWaitFactor * timeout_seconds_));
  fresh.timeout_seconds = timeout_seconds_;
  swap_process(fresh);
  fresh.set_aside = now;
  set_aside_.push_back(std::move(fresh));
}

void RunnerProcess::end_fresh_process() {
  if (set_aside_.empty()) return;
  if (running_ && print_fd_ >= 0) drain_prints(print_fd_);
  stop();
  Process back = std::move(set_aside_.back());
  set_aside_.pop_back();
  // The run's time was the run's own: the test's other calls keep the waiting they had left.
  back.deadline += std::chrono::steady_clock::now() - back.set_aside;
  swap_process(back);
  last_cpu_check_ = std::chrono::steady_clock::now();
}

void RunnerProcess::stop() {
  close_fd(request_fd_);
  close_fd(answer_fd_);
  inbox_begin_ = inbox_end_ = 0;  // the bytes of the pipe just closed
  close_fd(print_fd_);
  if (running_) kill_all(program_);
  running_ = false;
}

void RunnerProcess::fail(const std::string& what, Fault fault) {
  if (failure_.empty()) {
    failure_ = what;
    fault_ = fault;
  }
  stop();
  throw RunnerFailure(failure_);
}

std::string RunnerProcess::ended_how() {
  // The answer pipe closed: the runner ended (or closed it and lives on: then it is killed).
  int status = 0;
  if (!wait_until(program_, std::chrono::steady_clock::now() + std::chrono::milliseconds(500), status)) {
    status = kill_all(program_);
    return "your code closed its connection to the grader and kept running";
  }
  running_ = false;
  if (WIFEXITED(status)) {
    return "your code ended the program before answering (exit code " + std::to_string(WEXITSTATUS(status)) +
           ": an exit() call?)";
  }
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL && grading_memory_kills() > memory_kills_) {
    // The kernel stopped it at the grading's budget (grading_group.hpp), not a limit of its own.
    return "your code used more than this grading's memory budget of " +
           std::to_string(grading_memory_group_budget() >> 20) + " MiB (the kernel stopped it)";
  }
  return "your code " + describe_wait_status(status);
}

void RunnerProcess::drain_prints(int fd) {
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n <= 0) return;
    const std::size_t keep = std::min<std::size_t>(static_cast<std::size_t>(n), kMaxPrinted - std::min(kMaxPrinted, printed_.text.size()));
    printed_.text.append(buffer, keep);
    printed_.total += static_cast<std::size_t>(n);
  }
}

double RunnerProcess::cpu_seconds() const {
  // /proc/PID/stat: "pid (name) state ..." with utime, stime, cutime, cstime the 14th to 17th
  // fields; the name may hold spaces and parentheses, so the fields are counted after the last ')'.
  char path[64];
  std::snprintf(path, sizeof path, "/proc/%d/stat", static_cast<int>(program_.pid));
  const int fd = open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) return 0.0;
  char text[1024];
  const ssize_t n = read(fd, text, sizeof text - 1);
  close(fd);
  if (n <= 0) return 0.0;
  text[n] = '\0';
  const char* at = std::strrchr(text, ')');
  if (!at) return 0.0;
  unsigned long long ticks = 0;
  int field = 2;
  for (const char* p = at + 1; *p && field < 17; ++p) {
    if (*p != ' ') continue;
    ++field;
    if (field >= 14) ticks += std::strtoull(p + 1, nullptr, 10);
  }
  static const long per_second = sysconf(_SC_CLK_TCK);
  return per_second > 0 ? static_cast<double>(ticks) / static_cast<double>(per_second) : 0.0;
}

void RunnerProcess::read_answer(void* out, std::size_t size) {
  auto* p = static_cast<unsigned char*>(out);
  while (size > 0) {
    // What an earlier read brought beyond what it was asked for: the rest of this answer (its
    // payload, read with its header), or whatever else the runner wrote, the next read's, in
    // the order written, as if still in the pipe.
    if (inbox_begin_ < inbox_end_) {
      const std::size_t take = std::min(size, inbox_end_ - inbox_begin_);
      std::memcpy(p, inbox_.data() + inbox_begin_, take);
      inbox_begin_ += take;
      p += take;
      size -= take;
      continue;
    }
    // The CPU time is read from /proc every 50 ms of waiting at most: a tick's quick answer
    // costs no system call more.
    const auto now = std::chrono::steady_clock::now();
    if (now - last_cpu_check_ >= std::chrono::milliseconds(50)) {
      last_cpu_check_ = now;
      if (cpu_seconds() - cpu_at_begin_ > timeout_seconds_)
        fail("your code did not answer within " + seconds(timeout_seconds_) + " (an endless loop?)");
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - now);
    if (left.count() <= 0) {
      fail("your code did not answer within " + seconds(kWaitFactor * timeout_seconds_) +
           " of waiting (it may use " + seconds(timeout_seconds_) + " of computing): was it waiting for something?");
    }
    pollfd fds[2] = {{answer_fd_, POLLIN, 0}, {print_fd_, POLLIN, 0}};
    const int ready = poll(fds, 2, static_cast<int>(std::min<long long>(left.count(), 100)));
    if (ready < 0 && errno != EINTR) fail("the grader could not wait for your code", Fault::grader);
    if (ready <= 0) continue;
    if (fds[1].revents & POLLIN) drain_prints(print_fd_);
    if (fds[1].revents & (POLLHUP | POLLERR) && !(fds[1].revents & POLLIN)) fds[1].fd = -1;
    if (!(fds[0].revents & (POLLIN | POLLHUP | POLLERR))) continue;
    // As much as the pipe holds, up to the inbox's size: an answer written whole comes in one
    // read, its header and its payload.
    const ssize_t n = read(answer_fd_, inbox_.data(), inbox_.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(ended_how());
    inbox_begin_ = 0;
    inbox_end_ = static_cast<std::size_t>(n);
  }
}

std::vector<unsigned char> RunnerProcess::call(protocol::Function function, const std::vector<unsigned char>& arguments,
                                               std::size_t value_size) {
  ++calls_in_test_;
  if (!failure_.empty()) throw RunnerFailure(failure_);
  if (!running_) start();
  const protocol::Header request{protocol::kRequestMagic, ++sequence_, static_cast<std::uint32_t>(function),
                                 static_cast<std::uint32_t>(arguments.size())};
  std::vector<unsigned char>& message = outbox_;
  message.resize(sizeof request + arguments.size());
  std::memcpy(message.data(), &request, sizeof request);
  std::copy(arguments.begin(), arguments.end(), message.begin() + sizeof request);
  // A request is a few kilobytes, less than a pipe holds: it cannot block for long, and a
  // runner that no longer reads fails the write (EPIPE) when it is gone.
  for (std::size_t sent = 0; sent < message.size();) {
    const ssize_t n = write(request_fd_, message.data() + sent, message.size() - sent);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(ended_how());
    sent += static_cast<std::size_t>(n);
  }

  protocol::Header answer;
  read_answer(&answer, sizeof answer);
  std::string why;
  switch (check_answer(answer, request.sequence, value_size, why)) {
    case AnswerKind::kRejected: fail(why);
    case AnswerKind::kException: {
      std::string text(answer.size, '\0');
      read_answer(text.data(), text.size());
      throw StudentException("your code threw an exception: " + student_line(text, 200, text.size()));
    }
    case AnswerKind::kValue: break;
  }
  std::vector<unsigned char> value(value_size);
  read_answer(value.data(), value.size());
  return value;
}

}  // namespace opspace::grading
