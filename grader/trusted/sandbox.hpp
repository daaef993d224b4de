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

/// What to run and what it may see.
struct SandboxSpec {
  std::vector<std::string> argv;  ///< argv[0]: absolute path of the program
  std::vector<std::string> env;   ///< its whole environment ("NAME=value")
  std::string work_dir;           ///< its working folder (absolute), visible
  bool work_dir_writable = false;  ///< read-write (the compiler's output) or read-only
  std::vector<std::string> visible;  ///< absolute paths shown read-only besides /usr and /etc
  Limits limits;                  ///< resource limits
  std::vector<std::pair<int, int>> fds;  ///< {descriptor in the program, descriptor of the grader}
  std::string user;               ///< when the grader is root: run as this user (must exist)
  bool isolate = true;            ///< false: only a new session and the descriptors (debugging)
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

/// The user a root grader runs student code as: OPSPACE_SANDBOX_USER if set, else
/// "opspace-runner" if it exists, else "nobody". Empty when the grader is not root.
std::string default_sandbox_user();

/// "killed by signal 11 (Segmentation fault)", "exited with code 3": a wait status in words.
std::string describe_wait_status(int status);

}  // namespace opspace::grading
