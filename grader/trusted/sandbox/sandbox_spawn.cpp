// Starting a program in the sandbox of sandbox.hpp: spawn() fills the child's plan
// (sandbox_plan.hpp) with what each mechanism needs, then tries the namespaces from the most
// to the least until one works. Everything the child needs is prepared before clone(), so
// that between clone() and execve() the child makes only system calls (sandbox_child.cpp).
// The one thing that needs the child's pid, its seccomp filter (sandbox_seccomp.hpp), is
// built by the parent after clone() and read by the child from a pipe.
#include "sandbox/sandbox.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <stdexcept>

#include "sandbox/grading_group.hpp"
#include "sandbox/sandbox_plan.hpp"
#include "sandbox/sandbox_seccomp.hpp"

namespace opspace::grading {

namespace {

using sandbox_internal::ChildPlan;
using sandbox_internal::forget;
using sandbox_internal::live_programs;
using sandbox_internal::programs_lock;

// A child that will not start: killed, reaped and forgotten, its pipes closed (-1: none).
void abandon(pid_t pid, int error_fd, int filter_fd) {
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  forget(pid);
  close(error_fd);
  if (filter_fd >= 0) close(filter_fd);
}

// The pipes of one try, both ends of each (-1: none): the child's report of a failed step, which
// its execve() closes, and with seccomp the filter it waits for.
struct Pipes {
  int error_read = -1, error_write = -1;
  int filter_read = -1, filter_write = -1;
};

bool open_pipes(bool seccomp, Pipes& pipes) {
  int error_pipe[2];
  if (pipe2(error_pipe, O_CLOEXEC) != 0) return false;
  int filter_pipe[2] = {-1, -1};
  if (seccomp && pipe2(filter_pipe, O_CLOEXEC) != 0) {
    close(error_pipe[0]);
    close(error_pipe[1]);
    return false;
  }
  pipes = {error_pipe[0], error_pipe[1], filter_pipe[0], filter_pipe[1]};
  return true;
}

// The namespaces of `flags` in the plan: a mount namespace (with a PID namespace) has a new root.
void plan_namespaces(ChildPlan& plan, const SandboxSpec& spec, unsigned long flags) {
  plan.user_namespace = (flags & CLONE_NEWUSER) != 0;
  plan.mount_namespace = plan.pid_namespace = (flags & CLONE_NEWNS) != 0;
  plan.mounts.clear();
  if (plan.mount_namespace) sandbox_internal::plan_root(plan, spec);
}

// clone() with `flags`, the child running the plan up to execve(). Under the programs' lock: the
// pid is among the live programs before another thread's search for orphans can see the child
// (sandbox_programs.cpp). -1 and its `error` (errno) if it failed.
long clone_child(ChildPlan& plan, unsigned long flags, int& error) {
  std::fflush(nullptr);
  const std::lock_guard<std::mutex> hold(programs_lock());
  const long pid = syscall(SYS_clone, flags | SIGCHLD, nullptr, nullptr, nullptr, nullptr);
  if (pid == 0) sandbox_internal::child_main(plan);
  error = errno;
  if (pid > 0) live_programs().insert(static_cast<pid_t>(pid));
  return pid;
}

// Sends the child its seccomp filter (an instruction count, then the program), which names the
// child's pid as it sees it: 1, the init of its new PID namespace, or the one clone gave. Empty,
// or what failed.
std::string send_filter(int fd, pid_t pid, unsigned long flags, const SandboxSpec& spec, const ChildPlan& plan) {
  std::string failed;
  try {
    const std::vector<sock_filter> filter =
        seccomp_filter((flags & CLONE_NEWPID) ? 1 : pid, spec.runner ? plan.argv[0] : nullptr);
    const auto count = static_cast<std::uint32_t>(filter.size());
    std::string message(reinterpret_cast<const char*>(&count), sizeof count);
    message.append(reinterpret_cast<const char*>(filter.data()), filter.size() * sizeof(sock_filter));
    for (std::size_t sent = 0; sent < message.size() && failed.empty();) {
      const ssize_t n = write(fd, message.data() + sent, message.size() - sent);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) failed = std::string("send the seccomp filter: ") + std::strerror(errno);
      else sent += static_cast<std::size_t>(n);
    }
  } catch (const std::exception& e) {
    failed = e.what();
  }
  return failed;
}

// Whether the program started: the child reports a failed step (`why`), or closes the pipe by
// starting the program. It makes only system calls until then, so 30 s means it is stuck: it
// is killed and reported.
bool program_started(pid_t pid, int error_fd, std::string& why) {
  char message[256];
  ssize_t n = -1;
  pollfd wait_exec{error_fd, POLLIN, 0};
  int ready;
  do {
    ready = poll(&wait_exec, 1, 30000);
  } while (ready < 0 && errno == EINTR);
  if (ready == 0) {
    std::snprintf(message, sizeof message, "%s", "start the program within 30 s");
    n = static_cast<ssize_t>(std::strlen(message));
    kill(pid, SIGKILL);
  } else {
    do {
      n = read(error_fd, message, sizeof message - 1);
    } while (n < 0 && errno == EINTR);
  }
  if (n <= 0) return true;
  message[n] = '\0';
  why = message;
  return false;
}

// One try at starting the program with namespace `flags`: its pid, or -1 with `why`.
pid_t attempt(ChildPlan& plan, const SandboxSpec& spec, unsigned long flags, std::string& why) {
  Pipes pipes;
  if (!open_pipes(plan.seccomp, pipes)) {
    why = "create a pipe";
    return -1;
  }
  plan.error_fd = pipes.error_write;
  plan.filter_read_fd = pipes.filter_read;
  plan.filter_write_fd = pipes.filter_write;
  plan_namespaces(plan, spec, flags);
  int clone_error = 0;
  const long cloned = clone_child(plan, flags, clone_error);
  close(pipes.error_write);
  if (plan.seccomp) close(pipes.filter_read);
  if (cloned < 0) {
    close(pipes.error_read);
    if (plan.seccomp) close(pipes.filter_write);
    why = std::string("start a process: ") + std::strerror(clone_error);
    return -1;
  }
  const auto pid = static_cast<pid_t>(cloned);
  // Into the grading's memory and process budget before it runs anything of its own (it waits
  // for its filter; grading_group.hpp).
  try {
    admit_to_grading_groups(pid);
  } catch (const std::exception& e) {
    abandon(pid, pipes.error_read, plan.seccomp ? pipes.filter_write : -1);
    why = e.what();
    return -1;
  }
  if (plan.seccomp) {
    const std::string failed = send_filter(pipes.filter_write, pid, flags, spec, plan);
    close(pipes.filter_write);
    if (!failed.empty()) {
      abandon(pid, pipes.error_read, -1);
      why = failed;
      return -1;
    }
  }
  const bool started = program_started(pid, pipes.error_read, why);
  close(pipes.error_read);
  if (started) return pid;
  waitpid(pid, nullptr, 0);
  forget(pid);
  return -1;
}

}  // namespace

Sandboxed spawn(const SandboxSpec& spec) {
  if (spec.argv.empty() || spec.argv[0].empty() || spec.argv[0][0] != '/')
    throw std::invalid_argument("sandbox: the program needs an absolute path");
  ChildPlan plan;
  plan.argv_storage = spec.argv;
  plan.env_storage = spec.env;
  for (std::string& a : plan.argv_storage) plan.argv.push_back(a.data());
  plan.argv.push_back(nullptr);
  for (std::string& e : plan.env_storage) plan.env.push_back(e.data());
  plan.env.push_back(nullptr);
  plan.fds = spec.fds;
  plan.work_dir = spec.work_dir;
  plan.isolate = spec.isolate;
  plan.limits = spec.limits;

  Protections on;
  sandbox_internal::plan_user(plan, spec, on);
  if (spec.isolate) {
    on.limits = true;
    plan.seccomp = on.seccomp = true;
    plan.filter.resize(BPF_MAXINSNS);
  }

  // Namespaces, from the most to the least: as root directly, else through a user namespace,
  // else none (a laptop without user namespaces, a container that forbids them, a chroot
  // whose root is not a mount point). A setup that fails is tried again with the next.
  const unsigned long namespaces = CLONE_NEWPID | CLONE_NEWNET | CLONE_NEWNS | CLONE_NEWIPC | CLONE_NEWUTS;
  std::vector<unsigned long> attempts;
  if (spec.isolate) {
    if (geteuid() == 0) attempts.push_back(namespaces);
    attempts.push_back(namespaces | CLONE_NEWUSER);
  }
  attempts.push_back(0);
  std::string failure = "no way to start a process";
  for (unsigned long flags : attempts) {
    std::string why;
    const pid_t pid = attempt(plan, spec, flags, why);
    if (pid > 0) {
      on.pid_namespace = on.no_network = on.private_files = flags != 0;
      return Sandboxed{pid, on};
    }
    failure = why;
  }
  throw std::runtime_error("sandbox: cannot " + failure + " (" + spec.argv[0] + ")");
}

}  // namespace opspace::grading
