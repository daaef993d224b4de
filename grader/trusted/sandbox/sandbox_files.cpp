// The sandboxed program's private view of the files, in its own mount namespace: a new root
// (a small tmpfs), four devices, a private /tmp, the /proc of its own PID namespace, the paths
// the grader gives (read-only) and its work folder; then chroot() into it. A tool (the
// compiler, the linker, nm) also sees the system's folders (/usr, /etc, /bin, /lib...); a
// runner sees none of them, only the files its program needs to start (the loader and its
// shared libraries, read-only): no compiler, no other program, nothing to execute but itself.
// What it does not see (the grader's own files, the home folders, the runners' cache, another
// problem's runner) it can neither read nor write. The parent plans the mounts (plan_root():
// lstat, readlink, the flags a remount must keep); the child makes them (child_mounts()).
#include <fcntl.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/temporary_folder.hpp"
#include "sandbox/sandbox_plan.hpp"

namespace opspace::grading::sandbox_internal {

namespace {

unsigned long locked_flags(const std::string& path) {
  struct statvfs s {};
  if (statvfs(path.c_str(), &s) != 0) return 0;
  unsigned long flags = 0;
  if (s.f_flag & ST_NOSUID) flags |= MS_NOSUID;
  if (s.f_flag & ST_NODEV) flags |= MS_NODEV;
  if (s.f_flag & ST_NOEXEC) flags |= MS_NOEXEC;
  if (s.f_flag & ST_NOATIME) flags |= MS_NOATIME;
  if (s.f_flag & ST_NODIRATIME) flags |= MS_NODIRATIME;
  if (s.f_flag & ST_RELATIME) flags |= MS_RELATIME;
  return flags;
}

// The folders above `path` in the new root, outermost first.
std::vector<std::string> parents(const std::string& root, const std::string& path) {
  std::vector<std::string> out;
  for (std::size_t slash = path.find('/', 1); slash != std::string::npos; slash = path.find('/', slash + 1))
    out.push_back(root + path.substr(0, slash));
  return out;
}

void add_mount(ChildPlan& plan, const std::string& path, bool writable, const std::string& source = "") {
  struct stat s {};
  if (lstat((source.empty() ? path : source).c_str(), &s) != 0) return;  // absent on this machine: nothing to show
  Mount m;
  m.source = source.empty() ? path : source;
  m.target = plan.root + path;
  m.writable = writable;
  m.make_dirs = parents(plan.root, path);
  if (S_ISLNK(s.st_mode)) {
    char target[4096];
    const ssize_t n = readlink(m.source.c_str(), target, sizeof target - 1);
    if (n <= 0) return;
    m.link.assign(target, static_cast<std::size_t>(n));
  } else {
    m.directory = S_ISDIR(s.st_mode);
    m.flags = locked_flags(m.source);
    if (m.directory) m.make_dirs.push_back(m.target);
  }
  plan.mounts.push_back(m);
}

void add_special(ChildPlan& plan, const std::string& path, const char* kind) {
  Mount m;
  m.source = kind;
  m.target = plan.root + path;
  m.make_dirs = parents(plan.root, path);
  m.make_dirs.push_back(m.target);
  plan.mounts.push_back(m);
}

// One empty folder per grader process: each sandbox mounts its new root there, in its own
// mount namespace, so the folder stays empty outside. Removed when the grader exits.
char g_root[64] = "";
void remove_root() {
  if (g_root[0]) rmdir(g_root);
}
std::string root_mount_point() {
  // Under a lock: the grader builds several runners at once, and two threads that both found
  // no folder would each make one, and leave one behind.
  static std::mutex lock;
  const std::lock_guard<std::mutex> hold(lock);
  if (!g_root[0]) {
    // The grader's pid in the name, as in TemporaryFolder's (common/temporary_folder.hpp).
    std::string pattern = "/tmp/opspace-sandbox-" + std::to_string(getpid()) + "-XXXXXX";
    if (!mkdtemp(pattern.data()))
      throw std::runtime_error(std::string("cannot create a sandbox folder in /tmp: ") + std::strerror(errno));
    std::snprintf(g_root, sizeof g_root, "%s", pattern.c_str());
    std::atexit(remove_root);
    track_folder(g_root);
  }
  return g_root;
}

}  // namespace

void plan_root(ChildPlan& plan, const SandboxSpec& spec) {
  plan.root = root_mount_point();
  if (!spec.runner) {
    for (const char* system : {"/usr", "/etc", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"})
      add_mount(plan, system, false);
  } else {
    // Each file at the path the loader looks for it, its content from the file the path
    // resolves to: the folders above it are plain folders of the new root, not the system's.
    for (const std::string& file : spec.runtime) {
      char resolved[PATH_MAX];
      if (realpath(file.c_str(), resolved)) add_mount(plan, file, false, resolved);
    }
  }
  for (const char* device : {"/dev/null", "/dev/zero", "/dev/urandom", "/dev/random"}) add_mount(plan, device, true);
  add_special(plan, "/tmp", spec.runner ? "tmpfs-noexec" : "tmpfs");
  if (plan.pid_namespace) add_special(plan, "/proc", "proc");
  for (const std::string& path : spec.visible) add_mount(plan, path, false);
  add_mount(plan, spec.work_dir, spec.work_dir_writable);
}

void child_mounts(const ChildPlan& plan) {
  if (mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) child_fail(plan, "make / private");
  if (mount("tmpfs", plan.root.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, "size=1m,mode=0755") != 0)
    child_fail(plan, "mount the new root");
  for (const Mount& m : plan.mounts) {
    for (const std::string& dir : m.make_dirs) {
      if (mkdir(dir.c_str(), 0755) != 0 && errno != EEXIST) child_fail(plan, "create a folder of the new root");
    }
    if (!m.link.empty()) {
      if (symlink(m.link.c_str(), m.target.c_str()) != 0) child_fail(plan, "create a link in the new root");
      continue;
    }
    if (m.source == "tmpfs" || m.source == "tmpfs-noexec") {
      // A tool's /tmp holds a compiler's temporary files; a runner's, which nothing of the
      // runner needs, no more than a few of its 1 MiB files (tmpfs is memory).
      const bool tool = m.source == "tmpfs";
      if (mount("tmpfs", m.target.c_str(), "tmpfs", MS_NOSUID | MS_NODEV | (tool ? 0 : MS_NOEXEC),
                tool ? "size=512m,mode=1777" : "size=16m,mode=1777") != 0)
        child_fail(plan, "mount /tmp");
      continue;
    }
    if (m.source == "proc") {
      // Only inside a PID namespace (the parent plans it only then); optional.
      mount("proc", m.target.c_str(), "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, nullptr);
      continue;
    }
    if (!m.directory) {
      const int fd = open(m.target.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
      if (fd < 0) child_fail(plan, "create a mount point in the new root");
      close(fd);
    }
    if (mount(m.source.c_str(), m.target.c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0)
      child_fail(plan, "bind a visible path");
    if (!m.writable &&
        mount(nullptr, m.target.c_str(), nullptr, MS_REMOUNT | MS_BIND | MS_RDONLY | m.flags, nullptr) != 0)
      child_fail(plan, "make a visible path read-only");
  }
  if (chdir(plan.root.c_str()) != 0 || chroot(".") != 0) child_fail(plan, "enter the new root");
}

}  // namespace opspace::grading::sandbox_internal
