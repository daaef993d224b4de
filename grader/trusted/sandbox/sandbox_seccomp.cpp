// The system-call filter of sandbox_seccomp.hpp, written with libseccomp (its names resolve
// to this architecture's system-call numbers; it checks the architecture and the x32 ABI).
#include "sandbox/sandbox_seccomp.hpp"

#include <linux/seccomp.h>
#include <sched.h>
#include <seccomp.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

namespace opspace::grading {

namespace {

// Denied with EPERM (the header says why). A name this architecture lacks cannot be called.
const char* const kDenied[] = {
    "ptrace",          "process_vm_readv",  "process_vm_writev", "pidfd_getfd",      "tkill",
    "pidfd_send_signal", "mount",           "umount2",           "pivot_root",       "chroot",
    "unshare",         "setns",             "bpf",               "perf_event_open",  "userfaultfd",
    "keyctl",          "add_key",           "request_key",       "kexec_load",       "init_module",
    "finit_module",    "delete_module",     "io_uring_setup",    "io_uring_enter",   "io_uring_register"};

struct Release {
  void operator()(void* context) const { seccomp_release(context); }
};

void check(int rc, const std::string& what) {
  if (rc != 0) throw std::runtime_error("seccomp filter: " + what + ": " + std::strerror(-rc));
}

void add(scmp_filter_ctx context, std::uint32_t action, const char* name, unsigned count,
         const scmp_arg_cmp* compare) {
  const int nr = seccomp_syscall_resolve_name(name);
  if (nr == __NR_SCMP_ERROR) return;
  check(seccomp_rule_add_array(context, action, nr, count, compare), std::string("rule for ") + name);
}

// A comparison of the first argument: what libseccomp's SCMP_A0 makes, without its compound
// literal (C99, which clang refuses in C++ with -Wpedantic).
scmp_arg_cmp first_argument(scmp_compare op, scmp_datum_t a, scmp_datum_t b = 0) {
  scmp_arg_cmp compare{};
  compare.arg = 0;
  compare.op = op;
  compare.datum_a = a;
  compare.datum_b = b;
  return compare;
}

}  // namespace

std::vector<sock_filter> seccomp_filter(pid_t self, const void* exec_path) {
  if (self <= 0) throw std::invalid_argument("seccomp filter: own pid must be positive");
  const std::unique_ptr<void, Release> owner(seccomp_init(SCMP_ACT_ALLOW));
  scmp_filter_ctx context = owner.get();
  if (!context) throw std::runtime_error("seccomp filter: libseccomp could not start a filter");
  check(seccomp_attr_set(context, SCMP_FLTATR_ACT_BADARCH, SCMP_ACT_KILL_PROCESS), "other architectures");
  const std::uint32_t eperm = SCMP_ACT_ERRNO(EPERM);
  for (const char* name : kDenied) add(context, eperm, name, 0, nullptr);

  // The arguments are compared as 64-bit values: a value with its high half set is refused
  // even where the kernel reads only the low half (an int).
  const scmp_arg_cmp not_unix = first_argument(SCMP_CMP_NE, AF_UNIX);
  add(context, SCMP_ACT_ERRNO(EACCES), "socket", 1, &not_unix);
  const auto own = static_cast<scmp_datum_t>(self);
  const scmp_arg_cmp not_self = first_argument(SCMP_CMP_NE, own);
  add(context, eperm, "tgkill", 1, &not_self);
  // kill(pid) is allowed for pid 0 and pid self: refused above self (and so every negative
  // pid, as an unsigned 64-bit value), and on 1 .. self-1. A rule compares an argument once,
  // so that range is cut into aligned blocks of 2^k pids, one rule each (at most 2 log2(self)):
  // a block [start, start + 2^k) is the pids whose bits above k equal start's.
  const scmp_arg_cmp above = first_argument(SCMP_CMP_GT, own);
  add(context, eperm, "kill", 1, &above);
  for (scmp_datum_t start = 1; start < own;) {
    scmp_datum_t size = start & (~start + 1);  // the largest power of two dividing start
    while (start + size > own) size /= 2;
    const scmp_arg_cmp block = first_argument(SCMP_CMP_MASKED_EQ, ~(size - 1), start);
    add(context, eperm, "kill", 1, &block);
    start += size;
  }

  if (exec_path) {
    const scmp_arg_cmp other_path =
        first_argument(SCMP_CMP_NE, static_cast<scmp_datum_t>(reinterpret_cast<std::uintptr_t>(exec_path)));
    add(context, eperm, "execve", 1, &other_path);
    add(context, eperm, "execveat", 0, nullptr);
    add(context, eperm, "setsid", 0, nullptr);
    // No second process: a thread shares the runner's address space, and so its 1 GiB; a new
    // process would bring another 1 GiB. clone() only with CLONE_THREAD (which the kernel
    // accepts only with CLONE_VM); clone3() passes its flags in memory that a filter cannot
    // read, so it answers ENOSYS, and glibc's pthread_create() then falls back to clone().
    const scmp_arg_cmp not_thread = first_argument(SCMP_CMP_MASKED_EQ, CLONE_THREAD, 0);
    add(context, eperm, "clone", 1, &not_thread);
    add(context, SCMP_ACT_ERRNO(ENOSYS), "clone3", 0, nullptr);
    add(context, eperm, "fork", 0, nullptr);
    add(context, eperm, "vfork", 0, nullptr);
  }

  // libseccomp 2.5 exports to a descriptor only: a memory file, read back.
  const int fd = memfd_create("opspace-seccomp", MFD_CLOEXEC);
  if (fd < 0) throw std::runtime_error(std::string("seccomp filter: memfd_create: ") + std::strerror(errno));
  std::vector<sock_filter> program;
  std::string error;
  const int rc = seccomp_export_bpf(context, fd);
  const off_t size = rc == 0 ? lseek(fd, 0, SEEK_END) : -1;
  if (rc != 0) {
    error = std::string("export: ") + std::strerror(-rc);
  } else if (size <= 0 || size % static_cast<off_t>(sizeof(sock_filter)) != 0) {
    error = "export: " + std::to_string(size) + " bytes";
  } else {
    program.resize(static_cast<std::size_t>(size) / sizeof(sock_filter));
    if (pread(fd, program.data(), static_cast<std::size_t>(size), 0) != size) error = "read back the export";
  }
  close(fd);
  if (!error.empty()) throw std::runtime_error("seccomp filter: " + error);
  return program;
}

bool install_seccomp_filter(const sock_filter* program, std::size_t size) {
  if (size == 0 || size > BPF_MAXINSNS) {
    errno = EINVAL;
    return false;
  }
  sock_fprog fprog{static_cast<unsigned short>(size), const_cast<sock_filter*>(program)};
  if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return false;
  return prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &fprog) == 0;
}

}  // namespace opspace::grading
