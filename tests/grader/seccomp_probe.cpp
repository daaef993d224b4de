// Tries system calls that the sandbox's filter refuses or allows (grader/trusted/
// sandbox_seccomp.hpp) and prints one line per call: its name, then 0 if it succeeded or the
// errno it failed with. test_sandbox_seccomp runs it under the filter. The arguments of each
// refused call make the kernel, without the filter, answer something else than the filter's
// EPERM (EACCES for socket): a pid no process can have (ESRCH), descriptor -1 (EBADF), a null
// pointer (EFAULT), a missing path (ENOENT), or a call that succeeds.
//   seccomp_probe [OTHER_PID]   also kill(OTHER_PID, 0), a live process of the same user
//   seccomp_probe x32           getpid through the x32 ABI (x86_64): the filter kills the probe
//   seccomp_probe processes     a second process by fork, vfork, clone and clone3, and a thread
#include <fcntl.h>
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <sys/uio.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

// PID_MAX_LIMIT + 1 (linux/threads.h: 4 * 1024 * 1024 on 64-bit): above any pid.
constexpr long kNoSuchPid = 4L * 1024 * 1024 + 1;

void report(const char* name, long result) {
  std::printf("%s %d\n", name, result < 0 ? errno : 0);
  std::fflush(stdout);
}

// A child started by the call that returned `child` ends at once; 0 if there was one.
long reap(long child) {
  if (child == 0) _exit(0);
  if (child > 0) waitpid(static_cast<pid_t>(child), nullptr, 0);
  return child < 0 ? -1 : 0;
}

// clone3()'s argument, its first version (linux/sched.h's struct clone_args, 64 bytes).
struct CloneArgs {
  std::uint64_t flags, pidfd, child_tid, parent_tid, exit_signal, stack, stack_size, tls;
};

void* nothing(void*) { return nullptr; }

// Each way of starting a process, then a thread: one line each, as report() writes them.
void processes() {
  report("fork", reap(fork()));
  report("vfork", reap(vfork()));
  report("clone_process", reap(syscall(SYS_clone, static_cast<long>(SIGCHLD), 0L, 0L, 0L, 0L)));
#ifdef SYS_clone3
  CloneArgs args{};
  args.exit_signal = SIGCHLD;
  report("clone3", reap(syscall(SYS_clone3, &args, sizeof args)));
#endif
  pthread_t thread;
  const int error = pthread_create(&thread, nullptr, &nothing, nullptr);
  if (error == 0) pthread_join(thread, nullptr);
  errno = error;
  report("thread", error == 0 ? 0 : -1);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "x32") == 0) {
#if defined(__x86_64__)
    syscall(0x40000000L + SYS_getpid);  // __X32_SYSCALL_BIT
#endif
    std::printf("x32 survived\n");
    return 0;
  }
  if (argc == 2 && std::strcmp(argv[1], "processes") == 0) {
    processes();
    return 0;
  }
  // Refused with EPERM whatever the arguments.
  report("ptrace", syscall(SYS_ptrace, 2L /* PTRACE_PEEKDATA */, kNoSuchPid, 0L, 0L));
  char byte = 0;
  iovec local{&byte, 1}, remote{nullptr, 1};
  report("process_vm_readv", syscall(SYS_process_vm_readv, kNoSuchPid, &local, 1L, &remote, 1L, 0L));
  report("tkill", syscall(SYS_tkill, kNoSuchPid, 0L));
  report("unshare", syscall(SYS_unshare, 0L));
  report("setns", syscall(SYS_setns, -1L, 0L));
  report("chroot", syscall(SYS_chroot, "/nonexistent-opspace-probe"));
  report("perf_event_open", syscall(SYS_perf_event_open, nullptr, 0L, -1L, -1L, 0L));
#ifdef SYS_io_uring_setup
  report("io_uring_setup", syscall(SYS_io_uring_setup, 1L, nullptr));
#endif
#ifdef SYS_pidfd_send_signal
  report("pidfd_send_signal", syscall(SYS_pidfd_send_signal, -1L, 0L, nullptr, 0L));
#endif
  // socket(): AF_UNIX only, else EACCES.
  report("socket_unix", socket(AF_UNIX, SOCK_STREAM, 0));
  report("socket_inet", socket(AF_INET, SOCK_STREAM, 0));
  report("socket_inet6", socket(AF_INET6, SOCK_DGRAM, 0));
  report("socket_netlink", socket(AF_NETLINK, SOCK_RAW, 0));
  // kill(): its own group (0) and itself only; tgkill(): itself only.
  report("kill_group", kill(0, 0));
  report("kill_self", kill(getpid(), 0));
  report("kill_all", kill(-1, 0));
  report("kill_no_such", syscall(SYS_kill, kNoSuchPid, 0L));
  if (argc == 2) report("kill_other", kill(static_cast<pid_t>(std::atol(argv[1])), 0));
  report("tgkill_self", syscall(SYS_tgkill, static_cast<long>(getpid()), static_cast<long>(syscall(SYS_gettid)), 0L));
  report("tgkill_no_such", syscall(SYS_tgkill, kNoSuchPid, kNoSuchPid, 0L));
  return 0;
}
