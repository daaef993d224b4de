// Private to the sandbox's files (sandbox.hpp is the public side). The plan of what a sandboxed
// child does between clone() and execve(): the parent prepares all of it before clone() (the
// child then makes only system calls, sandbox_child.cpp says why), and each file of the
// sandbox adds its mechanism's part of the plan and the child's step that applies it:
//   sandbox_spawn.cpp     spawn(): the plan, the namespaces tried, clone(), the filter sent
//   sandbox_child.cpp     the child's steps, in their order, up to execve()
//   sandbox_user.cpp      credentials: the ids of a user namespace, the switch to the sandbox user
//   sandbox_files.cpp     the private view of the files: the new root and its mounts
//   sandbox_limits.cpp    the resource limits (setrlimit)
//   sandbox_programs.cpp  the live programs, waiting for them, killing them and their orphans
//   sandbox_seccomp.cpp   the system-call filter
#pragma once

#include <linux/filter.h>
#include <sys/types.h>

#include <cstddef>
#include <mutex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "sandbox/sandbox.hpp"

namespace opspace::grading::sandbox_internal {

struct Mount {
  std::string source;   // host path
  std::string target;   // path inside the new root (absolute, prefixed with the root)
  bool directory = true;
  bool writable = false;
  unsigned long flags = 0;  // the source's locked flags (nosuid, nodev, noexec), kept on remount
  std::string link;     // non-empty: create a symbolic link to this instead of mounting
  std::vector<std::string> make_dirs;  // created, in order, right before this mount
};

struct ChildPlan {
  std::vector<std::string> argv_storage, env_storage;
  std::vector<char*> argv, env;
  std::vector<std::pair<int, int>> fds;
  int error_fd = -1;
  bool isolate = true;
  bool user_namespace = false;  // maps its own uid and gid first
  std::string uid_map, gid_map;  // "outer outer 1": its own ids, mapped onto themselves
  bool mount_namespace = false;
  bool pid_namespace = false;
  std::string root;  // the new root's mount point
  std::vector<Mount> mounts;
  std::string work_dir;
  bool drop_user = false;
  uid_t uid = 0;
  gid_t gid = 0;
  Limits limits;
  bool limit_processes = false;
  bool seccomp = false;
  // The filter depends on the child's own pid: the parent builds it after clone() and sends it
  // through this pipe (an instruction count, then the program), into this buffer.
  int filter_read_fd = -1, filter_write_fd = -1;
  std::vector<sock_filter> filter;  // BPF_MAXINSNS instructions, allocated before clone()
  std::size_t filter_size = 0;
};

// --- in the child, between clone() and execve(): only system calls -------------------------

// sandbox_child.cpp: reports a failed step to the parent and exits; runs the steps and execve().
[[noreturn]] void child_fail(const ChildPlan& plan, const char* step);
[[noreturn]] void child_main(ChildPlan& plan);

// sandbox_user.cpp
void child_map_ids(const ChildPlan& plan);
void child_drop_user(const ChildPlan& plan);

// sandbox_files.cpp
void child_mounts(const ChildPlan& plan);

// sandbox_limits.cpp
void child_limits(const ChildPlan& plan);

// --- in the parent ---------------------------------------------------------------------------

// sandbox_user.cpp: the id maps, and as root the user to switch to (throws if it cannot be).
void plan_user(ChildPlan& plan, const SandboxSpec& spec, Protections& on);

// sandbox_files.cpp: the mounts of the new root.
void plan_root(ChildPlan& plan, const SandboxSpec& spec);

// sandbox_programs.cpp: the programs spawn() started and that are not reaped yet, under
// programs_lock().
std::mutex& programs_lock();
std::set<pid_t>& live_programs();
void forget(pid_t pid);

}  // namespace opspace::grading::sandbox_internal
