// The sandboxed child, from clone() to execve() (sandbox_spawn.cpp starts it). Only system calls: the
// grader may be the parent of several sandboxed programs, and the child must not depend on the
// C library's state (locks, caches) inherited from it. child_main() keeps its steps in an order
// that matters: the filter is received before the descriptors are closed (its pipe is one); the
// ids are mapped before the mounts create folders (an unmapped id cannot); the limits come after
// the descriptors are moved (to 700 and 900, above a low RLIMIT_NOFILE); the switch to the
// sandbox user after the steps that need privileges (the mounts, chroot); the death signal
// after that switch, which resets it; the filter last, right before execve(), since it forbids
// some of the calls above (mount, chroot).
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstdint>

#include "sandbox/sandbox_plan.hpp"
#include "sandbox/sandbox_seccomp.hpp"

namespace opspace::grading::sandbox_internal {

namespace {

void child_descriptors(ChildPlan& plan) {
  // Move the error pipe and the sources out of the way first: one may have a target's number.
  plan.error_fd = fcntl(plan.error_fd, F_DUPFD_CLOEXEC, 900);
  if (plan.error_fd < 0) _exit(127);
  int moved[16];
  const std::size_t count = std::min<std::size_t>(plan.fds.size(), 16);
  for (std::size_t i = 0; i < count; ++i) {
    moved[i] = fcntl(plan.fds[i].second, F_DUPFD_CLOEXEC, 700);
    if (moved[i] < 0) child_fail(plan, "move a descriptor");
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (dup2(moved[i], plan.fds[i].first) < 0) child_fail(plan, "set a descriptor");
  }
  // Close everything else but the error pipe (close-on-exec, it reports exec's failure).
  for (int fd = 0; fd < 1024; ++fd) {
    bool keep = fd == plan.error_fd;
    for (std::size_t i = 0; i < count; ++i) keep = keep || fd == plan.fds[i].first;
    if (!keep) close(fd);
  }
}

bool read_exact(int fd, void* buffer, std::size_t size) {
  auto* at = static_cast<char*>(buffer);
  while (size > 0) {
    const ssize_t n = read(fd, at, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    at += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

// The filter the parent built for this child's pid (attempt() in sandbox_spawn.cpp).
void child_receive_filter(ChildPlan& plan) {
  close(plan.filter_write_fd);
  std::uint32_t count = 0;
  if (!read_exact(plan.filter_read_fd, &count, sizeof count) || count == 0 || count > plan.filter.size() ||
      !read_exact(plan.filter_read_fd, plan.filter.data(), count * sizeof(sock_filter)))
    child_fail(plan, "receive the seccomp filter");
  plan.filter_size = count;
  close(plan.filter_read_fd);
}

}  // namespace

void child_fail(const ChildPlan& plan, const char* step) {
  const int error = errno;
  char buffer[256];
  std::size_t n = 0;
  for (const char* p = step; *p && n < 120; ++p) buffer[n++] = *p;
  const char* separator = ": ";
  for (const char* p = separator; *p; ++p) buffer[n++] = *p;
  // strerror may allocate on some systems; the error number is enough.
  char digits[16];
  int k = 0;
  int e = error;
  do {
    digits[k++] = static_cast<char>('0' + e % 10);
    e /= 10;
  } while (e > 0 && k < 15);
  const char* prefix = "errno ";
  for (const char* p = prefix; *p; ++p) buffer[n++] = *p;
  while (k > 0) buffer[n++] = digits[--k];
  if (write(plan.error_fd, buffer, n) < 0) _exit(127);
  _exit(127);
}

void child_main(ChildPlan& plan) {
  // The grader's threads block SIGINT, SIGTERM and SIGHUP (interrupt.hpp); its programs start
  // with no signal blocked.
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  if (plan.seccomp) child_receive_filter(plan);
  if (plan.user_namespace) child_map_ids(plan);
  if (setsid() < 0) child_fail(plan, "start a new session");
  if (plan.isolate && plan.mount_namespace) child_mounts(plan);
  if (chdir(plan.work_dir.c_str()) != 0) child_fail(plan, "enter the work folder");
  child_descriptors(plan);
  if (plan.isolate) child_limits(plan);
  if (plan.drop_user) child_drop_user(plan);
  // Die with the grader (after the user change, which resets this setting).
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (plan.seccomp && !install_seccomp_filter(plan.filter.data(), plan.filter_size))
    child_fail(plan, "install the seccomp filter");
  execve(plan.argv[0], plan.argv.data(), plan.env.data());
  child_fail(plan, "start the program");
}

}  // namespace opspace::grading::sandbox_internal
