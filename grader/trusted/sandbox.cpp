// Starting a program in the sandbox of sandbox.hpp: spawn() fills the child's plan
// (sandbox_plan.hpp) with what each mechanism needs, then tries the namespaces from the most
// to the least until one works. Everything the child needs is prepared before clone(), so
// that between clone() and execve() the child makes only system calls (sandbox_child.cpp).
// The one thing that needs the child's pid, its seccomp filter (sandbox_seccomp.hpp), is
// built by the parent after clone() and read by the child from a pipe.
#include "sandbox.hpp"

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

#include "grading_group.hpp"
#include "interrupt.hpp"
#include "sandbox_plan.hpp"
#include "sandbox_seccomp.hpp"

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

// One try at starting the program with namespace `flags`: its pid, or -1 with `why`.
pid_t attempt(ChildPlan& plan, const SandboxSpec& spec, unsigned long flags, std::string& why) {
  int error_pipe[2];
  if (pipe2(error_pipe, O_CLOEXEC) != 0) {
    why = "create a pipe";
    return -1;
  }
  plan.error_fd = error_pipe[1];
  int filter_pipe[2] = {-1, -1};
  if (plan.seccomp && pipe2(filter_pipe, O_CLOEXEC) != 0) {
    close(error_pipe[0]);
    close(error_pipe[1]);
    why = "create a pipe";
    return -1;
  }
  plan.filter_read_fd = filter_pipe[0];
  plan.filter_write_fd = filter_pipe[1];
  plan.user_namespace = (flags & CLONE_NEWUSER) != 0;
  plan.mount_namespace = plan.pid_namespace = (flags & CLONE_NEWNS) != 0;
  plan.mounts.clear();
  if (plan.mount_namespace) sandbox_internal::plan_root(plan, spec);
  std::fflush(nullptr);
  std::unique_lock<std::mutex> hold(programs_lock());
  const long pid = syscall(SYS_clone, flags | SIGCHLD, nullptr, nullptr, nullptr, nullptr);
  if (pid == 0) sandbox_internal::child_main(plan);
  const int clone_error = errno;
  if (pid > 0) live_programs().insert(static_cast<pid_t>(pid));
  hold.unlock();
  close(error_pipe[1]);
  if (plan.seccomp) close(filter_pipe[0]);
  if (pid < 0) {
    close(error_pipe[0]);
    if (plan.seccomp) close(filter_pipe[1]);
    why = std::string("start a process: ") + std::strerror(clone_error);
    return -1;
  }
  // Into the grading's memory and process budget before it runs anything of its own (it waits
  // for its filter; grading_group.hpp).
  try {
    admit_to_grading_groups(static_cast<pid_t>(pid));
  } catch (const std::exception& e) {
    abandon(static_cast<pid_t>(pid), error_pipe[0], plan.seccomp ? filter_pipe[1] : -1);
    why = e.what();
    return -1;
  }
  if (plan.seccomp) {
    // The child's pid as it sees it: 1, the init of its new PID namespace, or the one clone gave.
    std::string failed;
    try {
      const std::vector<sock_filter> filter = seccomp_filter(
          (flags & CLONE_NEWPID) ? 1 : static_cast<pid_t>(pid), spec.runner ? plan.argv[0] : nullptr);
      const auto count = static_cast<std::uint32_t>(filter.size());
      std::string message(reinterpret_cast<const char*>(&count), sizeof count);
      message.append(reinterpret_cast<const char*>(filter.data()), filter.size() * sizeof(sock_filter));
      for (std::size_t sent = 0; sent < message.size() && failed.empty();) {
        const ssize_t n = write(filter_pipe[1], message.data() + sent, message.size() - sent);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) failed = std::string("send the seccomp filter: ") + std::strerror(errno);
        else sent += static_cast<std::size_t>(n);
      }
    } catch (const std::exception& e) {
      failed = e.what();
    }
    close(filter_pipe[1]);
    if (!failed.empty()) {
      abandon(static_cast<pid_t>(pid), error_pipe[0], -1);
      why = failed;
      return -1;
    }
  }
  // The child reports a failed step, or closes the pipe by starting the program. It makes only
  // system calls until then, so 30 s means it is stuck: it is killed and reported.
  char message[256];
  ssize_t n = -1;
  pollfd wait_exec{error_pipe[0], POLLIN, 0};
  int ready;
  do {
    ready = poll(&wait_exec, 1, 30000);
  } while (ready < 0 && errno == EINTR);
  if (ready == 0) {
    std::snprintf(message, sizeof message, "%s", "start the program within 30 s");
    n = static_cast<ssize_t>(std::strlen(message));
    kill(static_cast<pid_t>(pid), SIGKILL);
  } else {
    do {
      n = read(error_pipe[0], message, sizeof message - 1);
    } while (n < 0 && errno == EINTR);
  }
  close(error_pipe[0]);
  if (n <= 0) return static_cast<pid_t>(pid);
  message[n] = '\0';
  waitpid(static_cast<pid_t>(pid), nullptr, 0);
  forget(static_cast<pid_t>(pid));
  why = message;
  return -1;
}

}  // namespace

std::string Protections::missing() const {
  std::string out;
  auto add = [&out](bool on, const char* what) {
    if (!on) out += (out.empty() ? "" : ", ") + std::string(what);
  };
  add(own_user, "a separate user");
  add(pid_namespace, "a PID namespace");
  add(no_network, "a network namespace");
  add(private_files, "a private view of the files");
  add(seccomp, "the system-call filter");
  add(limits, "resource limits");
  return out;
}

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

namespace opspace::grading {

bool sandbox_complete(const Account& account, std::string& why) {
  const TemporaryFolder folder("/tmp/opspace-probe-");
  SandboxSpec spec;
  spec.argv = {"/usr/bin/true"};
  spec.work_dir = folder.path();
  spec.account = account;
  Sandboxed program;
  try {
    program = spawn(spec);
  } catch (const std::exception& e) {
    why = e.what();
    return false;
  }
  int status = 0;
  if (!wait_until(program, std::chrono::steady_clock::now() + std::chrono::seconds(30), status)) status = kill_all(program);
  Protections on = program.protections;
  // Without root, the user namespace is the separate identity: no uid of the grader's outside.
  if (geteuid() != 0) on.own_user = on.pid_namespace;
  why = on.missing();
  if (why.empty() && !(WIFEXITED(status) && WEXITSTATUS(status) == 0))
    why = "a trial program " + describe_wait_status(status);
  return why.empty();
}

}  // namespace opspace::grading
