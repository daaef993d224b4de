/// @file sandbox.hpp
/// Starting a program the grader does not trust (a student's runner, or the compiler on a
/// student's file) in a sandbox, and ending it with everything it started.
///
/// What the sandbox applies, each where the machine allows it (Protections says which):
/// - a new session, an emptied environment, only the descriptors it is given;
/// - resource limits: address space, CPU time, file size, open files, no core files, and
///   processes when it runs as its own user;
/// - as root: another, unprivileged user (setgroups, setresgid, setresuid);
/// - namespaces (as root, or through a user namespace): a PID namespace (its first process
///   is init: when it ends the kernel kills the rest), no network (a new network namespace),
///   and a private filesystem view that shows only /usr, /etc, the paths it is given and a
///   work folder;
/// - a seccomp filter (sandbox_seccomp.hpp, by libseccomp): no socket but AF_UNIX, no ptrace,
///   no signals but to itself or its group;
/// - the grader is a child subreaper, so that whatever it started and detached (setsid,
///   double fork) is re-parented to the grader and killed by kill_all().
#pragma once

#include <sys/types.h>

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace opspace::grading {

/// Resource limits of a sandboxed program (setrlimit); 0 leaves a limit as it is.
struct Limits {
  unsigned long long address_space = 0;  ///< bytes (RLIMIT_AS; not with AddressSanitizer)
  unsigned long long cpu_seconds = 0;    ///< RLIMIT_CPU: SIGXCPU, then SIGKILL one second later
  unsigned long long file_size = 0;      ///< RLIMIT_FSIZE, bytes one file may grow to
  unsigned long long open_files = 0;     ///< RLIMIT_NOFILE
  unsigned long long processes = 0;      ///< RLIMIT_NPROC, only when it runs as its own user
};

/// The unprivileged identity a root grader runs student code as (sandbox_user.cpp).
struct Account {
  uid_t uid = 0;      ///< 0: none (the grader is not root, or runs without the sandbox)
  gid_t gid = 0;
  std::string name;   ///< for messages: "opspace-runner", "uid 3500007"
  bool own = false;   ///< this grading's alone: no other grading runs as it at the same time
};

/// What to run and what it may see.
struct SandboxSpec {
  std::vector<std::string> argv;  ///< argv[0]: absolute path of the program
  std::vector<std::string> env;   ///< its whole environment ("NAME=value")
  std::string work_dir;           ///< its working folder (absolute), visible
  bool work_dir_writable = false;  ///< read-write (the compiler's output) or read-only
  std::vector<std::string> visible;  ///< absolute paths shown read-only besides /usr and /etc
  Limits limits;                  ///< resource limits
  std::vector<std::pair<int, int>> fds;  ///< {descriptor in the program, descriptor of the grader}
  Account account;                ///< when the grader is root: run as this account
  bool isolate = true;            ///< false: only a new session and the descriptors (debugging)
  /// A runner rather than a tool: it sees none of the system's folders, only `runtime` (the
  /// files its program needs to start: loader and shared libraries) besides its work folder and
  /// `visible`; it may not execve() anything but its own program, nor start a new session.
  bool runner = false;
  std::vector<std::string> runtime;  ///< absolute paths of files, shown read-only (a runner's)
};

/// Which protections a sandboxed program had.
struct Protections {
  bool own_user = false;      ///< ran as an unprivileged user other than the grader's
  bool pid_namespace = false;  ///< its processes die with it, and it cannot see others
  bool no_network = false;     ///< a network namespace without interfaces
  bool private_files = false;  ///< saw only /usr, /etc, its work folder and the given paths
  bool seccomp = false;        ///< the system-call filter
  bool limits = false;         ///< the resource limits
  /// "separate user, PID namespace" ...: the protections that were off, for the report.
  std::string missing() const;
};

/// A program started by spawn().
struct Sandboxed {
  pid_t pid = -1;           ///< its process (init of its PID namespace, if it has one)
  Protections protections;  ///< what it runs under
};

/// Starts spec.argv in the sandbox. Throws std::runtime_error (with the reason) if the
/// program could not be started at all; a protection the machine lacks is left off and
/// recorded in Protections instead.
Sandboxed spawn(const SandboxSpec& spec);

/// Kills the program and everything it started (PID namespace, or every process the grader
/// inherited as subreaper), and reaps them. Returns the program's wait status.
int kill_all(const Sandboxed& program);

/// Sends SIGKILL to every program spawn() started that is still live, and to its process
/// group, without reaping them: for a grader that is about to end (interrupt.hpp).
void kill_live_programs();

/// Waits for the program until `deadline`: true with its wait status if it ended, false if
/// the time ran out (it is still running). Reaps re-parented descendants on the way.
bool wait_until(const Sandboxed& program, std::chrono::steady_clock::time_point deadline, int& status);

/// Makes this process a child subreaper and ignores SIGPIPE: call once at the grader's start.
void become_subreaper();

/// The account a root grader runs student code as. `named` empty: an account of this grading's
/// own, a uid no other grading holds at the same time (a lock file per uid, under /run, held
/// until the grader ends), where the kernel maps that range; else (or when `named` is given)
/// the named user ("opspace-runner" if it exists, else "nobody"), which concurrent gradings
/// share. Empty when the grader is not root. Throws std::runtime_error for an unknown or root user.
Account grading_account(const std::string& named);

/// Kills every process of `account` (a helper switches to it and sends SIGKILL to all it can):
/// whatever this grading's student code left running anywhere. Only for an account of its own.
void kill_account(const Account& account);

/// Whether the sandbox holds everything it promises on this machine (a separate user when the
/// grader is root, a PID namespace, no network, a private view of the files, the filter, the
/// limits): a trial start of /bin/true. `why` names what was off.
bool sandbox_complete(const Account& account, std::string& why);

/// "killed by signal 11 (Segmentation fault)", "exited with code 3": a wait status in words.
std::string describe_wait_status(int status);

}  // namespace opspace::grading
