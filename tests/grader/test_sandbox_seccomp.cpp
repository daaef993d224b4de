// The sandbox's system-call filter (grader/trusted/sandbox/sandbox_seccomp.hpp): seccomp_probe
// tries refused and allowed calls, under the filter alone (its pid is any, so kill()'s rule for
// other pids is exercised below and above its own) and in the grader's whole sandbox.
#include <doctest/doctest.h>
#include <signal.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "sandbox/sandbox.hpp"
#include "sandbox/sandbox_seccomp.hpp"

namespace grading = opspace::grading;

namespace {

using Results = std::map<std::string, int>;

// The probe's environment: under AddressSanitizer (the asan preset) its leak check at exit would
// need ptrace, which the filter refuses (the grader's runners get the same, grader/trusted/judge/grade_problems.cpp).
const char* const kProbeEnvironment = "ASAN_OPTIONS=detect_leaks=0";

std::string read_all(int fd) {
  std::string out;
  char buffer[4096];
  for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    out.append(buffer, static_cast<std::size_t>(n));
  }
  return out;
}

Results parse(const std::string& text) {
  Results out;
  std::istringstream lines(text);
  std::string name;
  int error = 0;
  while (lines >> name >> error) out[name] = error;
  return out;
}

// The probe with `arguments`, under the filter built for its own pid (a runner's filter, whose
// one execve() is the probe's, if `runner`); its output and wait status.
std::string run_filtered(const std::vector<std::string>& arguments, int& status, bool runner = false) {
  int out[2];
  REQUIRE(pipe(out) == 0);
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    dup2(out[1], 1);
    close(out[0]);
    close(out[1]);
    std::vector<char*> argv{const_cast<char*>(OPSPACE_SECCOMP_PROBE)};
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const std::vector<sock_filter> filter = grading::seccomp_filter(getpid(), runner ? argv[0] : nullptr);
    if (!grading::install_seccomp_filter(filter.data(), filter.size())) _exit(120);
    char* env[] = {const_cast<char*>(kProbeEnvironment), nullptr};
    execve(argv[0], argv.data(), env);
    _exit(121);
  }
  close(out[1]);
  const std::string text = read_all(out[0]);
  close(out[0]);
  REQUIRE(waitpid(pid, &status, 0) == pid);
  return text;
}

// The refusals that hold wherever the probe runs, and the calls that stay allowed.
void check_common(const Results& r) {
  for (const char* refused : {"ptrace", "process_vm_readv", "tkill", "unshare", "setns", "chroot",
                              "perf_event_open", "io_uring_setup", "pidfd_send_signal", "kill_all",
                              "kill_no_such", "tgkill_no_such"}) {
    CAPTURE(refused);
    REQUIRE(r.count(refused) == 1);
    CHECK(r.at(refused) == EPERM);
  }
  for (const char* network : {"socket_inet", "socket_inet6", "socket_netlink"}) {
    CAPTURE(network);
    REQUIRE(r.count(network) == 1);
    CHECK(r.at(network) == EACCES);
  }
  for (const char* allowed : {"socket_unix", "kill_group", "kill_self", "tgkill_self"}) {
    CAPTURE(allowed);
    REQUIRE(r.count(allowed) == 1);
    CHECK(r.at(allowed) == 0);
  }
}

}  // namespace

TEST_CASE("the filter refuses tracing, kernel interfaces, the network and signals to others") {
  int status = 0;
  const std::string text = run_filtered({std::to_string(getpid())}, status);
  CAPTURE(text);
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  const Results r = parse(text);
  check_common(r);
  // This test's process, alive and of the same user: only the filter refuses it.
  REQUIRE(r.count("kill_other") == 1);
  CHECK(r.at("kill_other") == EPERM);
}

TEST_CASE("kill() and tgkill() are refused for every pid but 0 and its own, on either side of it") {
  // Under the filter built for pid `self` (the child's real pid is another: the filter compares
  // numbers), each call sends signal 999, which does not exist: the kernel then answers ESRCH
  // or EINVAL, never EPERM, so EPERM is the filter's refusal. kill()'s rule cuts 1 .. self-1
  // into blocks of 2^k pids: the pids around each power of two below self cross their edges.
  // self: 1, the init of a new PID namespace (no pid below it but 0); 2 and 3, the fewest
  // blocks below; 1000, not near a power of two; 4097 = 2^12 + 1, whose 1 .. 4096 ends in a
  // one-pid block; 4194304, PID_MAX_LIMIT (linux/threads.h), the largest pid. Refused besides:
  // the pid after self, -1 (every process), -self (its group by number), a pid above
  // PID_MAX_LIMIT, and 64-bit values whose low half is self or 0 (the kernel reads an int).
  for (const long self : {1L, 2L, 3L, 1000L, 4097L, 4194304L}) {
    CAPTURE(self);
    std::vector<long> refused = {self + 1, -1, -self, 4194305L, (1L << 32) + self, 1L << 32};
    for (long power = 1; power < self; power *= 2) {
      for (const long pid : {power - 1, power, power + 1}) {
        if (pid >= 1 && pid < self) refused.push_back(pid);
      }
    }
    refused.push_back(self - 1);
    if (self - 1 < 1) refused.pop_back();
    const std::vector<long> allowed = {0, self};
    const std::vector<sock_filter> filter = grading::seccomp_filter(static_cast<pid_t>(self));
    int out[2];
    REQUIRE(pipe(out) == 0);
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      close(out[0]);
      if (!grading::install_seccomp_filter(filter.data(), filter.size())) _exit(120);
      const std::vector<long>* lists[] = {&allowed, &refused};
      for (const std::vector<long>* pids : lists) {
        for (const long pid : *pids) {
          const bool kill_refused = syscall(SYS_kill, pid, 999L) < 0 && errno == EPERM;
          const bool tgkill_refused = syscall(SYS_tgkill, pid, pid, 999L) < 0 && errno == EPERM;
          const char answer[2] = {kill_refused ? 'R' : 'a', tgkill_refused ? 'R' : 'a'};
          if (write(out[1], answer, 2) != 2) _exit(121);
        }
      }
      _exit(0);
    }
    close(out[1]);
    const std::string answers = read_all(out[0]);
    close(out[0]);
    int status = 0;
    REQUIRE(waitpid(child, &status, 0) == child);
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) == 0);
    REQUIRE(answers.size() == 2 * (allowed.size() + refused.size()));
    for (std::size_t i = 0; i < allowed.size(); ++i) {
      CAPTURE(allowed[i]);
      CHECK_MESSAGE(answers[2 * i] == 'a', "kill");
      // tgkill() is allowed to its own pid only: not to 0.
      CHECK_MESSAGE(answers[2 * i + 1] == (allowed[i] == self ? 'a' : 'R'), "tgkill");
    }
    for (std::size_t i = 0; i < refused.size(); ++i) {
      CAPTURE(refused[i]);
      const std::size_t at = 2 * (allowed.size() + i);
      CHECK_MESSAGE(answers[at] == 'R', "kill");
      CHECK_MESSAGE(answers[at + 1] == 'R', "tgkill");
    }
  }
}

TEST_CASE("a runner may start a thread but no second process, and a tool such as the compiler may start both") {
  // fork, vfork and clone without CLONE_THREAD would each bring a process with an address space
  // (and a limit) of its own; clone3 hides its flags from the filter and answers ENOSYS, after
  // which glibc's pthread_create() uses clone() with CLONE_THREAD.
  for (const bool runner : {true, false}) {
    CAPTURE(runner);
    int status = 0;
    const std::string text = run_filtered({"processes"}, status, runner);
    CAPTURE(text);
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) == 0);
    const Results r = parse(text);
    for (const char* call : {"fork", "vfork", "clone_process"}) {
      CAPTURE(call);
      REQUIRE(r.count(call) == 1);
      CHECK_MESSAGE(r.at(call) == (runner ? EPERM : 0), "a runner's second process is refused with EPERM");
    }
#ifdef SYS_clone3
    REQUIRE(r.count("clone3") == 1);
    CHECK(r.at("clone3") == (runner ? ENOSYS : 0));
#endif
    REQUIRE(r.count("thread") == 1);
    CHECK_MESSAGE(r.at("thread") == 0, "a thread shares the runner's address space and its limit: allowed");
  }
}

#if defined(__x86_64__)
TEST_CASE("a system call through the x32 ABI kills the process") {
  int status = 0;
  const std::string text = run_filtered({"x32"}, status);
  CAPTURE(text);
  CHECK(WIFSIGNALED(status));
  CHECK(text.find("survived") == std::string::npos);
}
#endif

TEST_CASE("in the grader's sandbox the same calls are refused") {
  int out[2];
  REQUIRE(pipe(out) == 0);
  char pattern[] = "/tmp/opspace-seccomp-test-XXXXXX";
  REQUIRE(mkdtemp(pattern) != nullptr);
  grading::SandboxSpec spec;
  spec.argv = {OPSPACE_SECCOMP_PROBE};
  spec.env = {kProbeEnvironment};
  spec.work_dir = pattern;
  spec.visible = {OPSPACE_SECCOMP_PROBE};
  spec.fds = {{1, out[1]}};
  spec.account = grading::grading_account("");
  const grading::Sandboxed program = grading::spawn(spec);
  close(out[1]);
  const std::string text = read_all(out[0]);
  close(out[0]);
  int status = 0;
  const bool ended = grading::wait_until(program, std::chrono::steady_clock::now() + std::chrono::seconds(30), status);
  if (!ended) status = grading::kill_all(program);
  std::filesystem::remove_all(pattern);
  CAPTURE(text);
  REQUIRE(ended);
  CHECK(program.protections.seccomp);
  REQUIRE(WIFEXITED(status));
  check_common(parse(text));
}
