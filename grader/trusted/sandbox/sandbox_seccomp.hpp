/// @file sandbox_seccomp.hpp
/// The sandbox's system-call filter (sandbox.hpp), built by libseccomp for this machine's
/// architecture. The policy:
/// - denied with EPERM: tracing and reading other processes (ptrace, process_vm_readv/writev,
///   pidfd_getfd), signals by thread id or pidfd (tkill, pidfd_send_signal), changing the
///   sandbox (mount, umount2, pivot_root, chroot, unshare, setns) and kernel interfaces a
///   runner has no use for (bpf, perf_event_open, userfaultfd, the key ring, io_uring,
///   loading kernels and modules);
/// - socket(): AF_UNIX only, any other domain refused with EACCES (no network, whatever the
///   namespaces);
/// - kill(pid, sig): only to its own process group (pid 0) or to itself, else EPERM;
///   tgkill(tgid, ...): only to itself (abort() and raise() use it), else EPERM;
/// - another architecture or ABI (x32 on x86_64, i386 through int 0x80) kills the process;
/// - for a runner only: execve() only with the very path pointer the sandbox's own execve()
///   passes (its program; after it, the new program's memory holds no such pointer unless it
///   maps one there, and the runner's view of the files holds nothing else to execute),
///   execveat() never, and no new session (setsid: the scheduler groups a session's processes,
///   so that a runner's processes share one group's time rather than taking a group each),
///   and no second process: fork() and vfork() refused, clone() only for a thread (CLONE_THREAD,
///   in the runner's own address space and its limit), clone3() answers ENOSYS.
#pragma once

#include <linux/filter.h>
#include <sys/types.h>

#include <cstddef>
#include <vector>

namespace opspace::grading {

/// The filter, as a BPF program, for a process whose own pid, as it sees it, is `self` (1 in
/// a new PID namespace). `exec_path`: for a runner, the address of the path its execve() will
/// pass (the only execve() allowed); null for a tool (the compiler starts its own programs).
/// Throws std::runtime_error if libseccomp cannot build it.
std::vector<sock_filter> seccomp_filter(pid_t self, const void* exec_path = nullptr);

/// Installs the BPF program of `size` instructions in the calling process for good
/// (no_new_privs, then the filter): only system calls, so a child between clone() and execve()
/// may call it. False with errno set if the kernel refused.
bool install_seccomp_filter(const sock_filter* program, std::size_t size);

}  // namespace opspace::grading
