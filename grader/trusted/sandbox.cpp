// The sandbox of sandbox.hpp. Everything the child needs is prepared before clone(), so that
// between clone() and execve() the child makes only system calls: the grader may be the
// parent of several sandboxed programs, and the child must not depend on the C library's
// state (locks, caches) inherited from it. The one thing that needs the child's pid, its
// seccomp filter (sandbox_seccomp.hpp), is built by the parent after clone() and read by the
// child from a pipe.
#include "sandbox.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <pwd.h>
#include <sched.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#include "interrupt.hpp"
#include "sandbox_seccomp.hpp"

namespace opspace::grading {

namespace {

// --- what the child does, prepared by the parent --------------------------------------------

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

// Reports a failed step to the parent and exits; only system calls.
[[noreturn]] void child_fail(const ChildPlan& plan, const char* step) {
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

bool write_file(const char* path, const char* text) {
  const int fd = open(path, O_WRONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const std::size_t size = std::strlen(text);
  const bool ok = write(fd, text, size) == static_cast<ssize_t>(size);
  close(fd);
  return ok;
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
    if (m.source == "tmpfs") {
      if (mount("tmpfs", m.target.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, "size=512m,mode=1777") != 0)
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

void child_limits(const ChildPlan& plan) {
  auto set = [&plan](int resource, unsigned long long value, const char* what) {
    if (value == 0) return;
    rlimit limit{value, value};
    if (resource == RLIMIT_CPU) limit.rlim_max = value + 1;  // SIGXCPU first, then SIGKILL
    if (setrlimit(resource, &limit) != 0) child_fail(plan, what);
  };
  set(RLIMIT_AS, plan.limits.address_space, "limit the address space");
  set(RLIMIT_CPU, plan.limits.cpu_seconds, "limit the CPU time");
  set(RLIMIT_FSIZE, plan.limits.file_size, "limit the file size");
  set(RLIMIT_NOFILE, plan.limits.open_files, "limit the open files");
  if (plan.limit_processes) set(RLIMIT_NPROC, plan.limits.processes, "limit the processes");
  rlimit no_core{0, 0};
  if (setrlimit(RLIMIT_CORE, &no_core) != 0) child_fail(plan, "forbid core files");
}

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

// The filter the parent built for this child's pid (attempt()).
void child_receive_filter(ChildPlan& plan) {
  close(plan.filter_write_fd);
  std::uint32_t count = 0;
  if (!read_exact(plan.filter_read_fd, &count, sizeof count) || count == 0 || count > plan.filter.size() ||
      !read_exact(plan.filter_read_fd, plan.filter.data(), count * sizeof(sock_filter)))
    child_fail(plan, "receive the seccomp filter");
  plan.filter_size = count;
  close(plan.filter_read_fd);
}

[[noreturn]] void child_main(ChildPlan& plan) {
  // The grader's threads block SIGINT, SIGTERM and SIGHUP (interrupt.hpp); its programs start
  // with no signal blocked.
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  if (plan.seccomp) child_receive_filter(plan);
  if (plan.user_namespace) {
    // Map our own ids into the new user namespace: execve then drops the capabilities this
    // process holds there, since its uid is not 0.
    if (!write_file("/proc/self/uid_map", plan.uid_map.c_str())) child_fail(plan, "map the user id");
    if (!write_file("/proc/self/setgroups", "deny")) child_fail(plan, "deny setgroups");
    if (!write_file("/proc/self/gid_map", plan.gid_map.c_str())) child_fail(plan, "map the group id");
  }
  if (setsid() < 0) child_fail(plan, "start a new session");
  if (plan.isolate && plan.mount_namespace) child_mounts(plan);
  if (chdir(plan.work_dir.c_str()) != 0) child_fail(plan, "enter the work folder");
  child_descriptors(plan);
  if (plan.isolate) child_limits(plan);
  if (plan.drop_user) {
    // Raw system calls: the C library's wrappers would wait for the grader's other threads,
    // which do not exist in this process.
    if (syscall(SYS_setgroups, 0, nullptr) != 0) child_fail(plan, "drop the supplementary groups");
    if (syscall(SYS_setresgid, plan.gid, plan.gid, plan.gid) != 0) child_fail(plan, "change group");
    if (syscall(SYS_setresuid, plan.uid, plan.uid, plan.uid) != 0) child_fail(plan, "change user");
    if (syscall(SYS_setuid, 0) == 0) child_fail(plan, "the user change did not hold");
  }
  // Die with the grader (after the user change, which resets this setting).
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (plan.seccomp && !install_seccomp_filter(plan.filter.data(), plan.filter_size))
    child_fail(plan, "install the seccomp filter");
  execve(plan.argv[0], plan.argv.data(), plan.env.data());
  child_fail(plan, "start the program");
}

// --- the new root ----------------------------------------------------------------------------

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

void add_mount(ChildPlan& plan, const std::string& path, bool writable) {
  struct stat s {};
  if (lstat(path.c_str(), &s) != 0) return;  // absent on this machine: nothing to show
  Mount m;
  m.source = path;
  m.target = plan.root + path;
  m.writable = writable;
  m.make_dirs = parents(plan.root, path);
  if (S_ISLNK(s.st_mode)) {
    char target[4096];
    const ssize_t n = readlink(path.c_str(), target, sizeof target - 1);
    if (n <= 0) return;
    m.link.assign(target, static_cast<std::size_t>(n));
  } else {
    m.directory = S_ISDIR(s.st_mode);
    m.flags = locked_flags(path);
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
  if (!g_root[0]) {
    // The grader's pid in the name, as in TemporaryFolder's (interrupt.hpp).
    std::string pattern = "/tmp/opspace-sandbox-" + std::to_string(getpid()) + "-XXXXXX";
    if (!mkdtemp(pattern.data()))
      throw std::runtime_error(std::string("cannot create a sandbox folder in /tmp: ") + std::strerror(errno));
    std::snprintf(g_root, sizeof g_root, "%s", pattern.c_str());
    std::atexit(remove_root);
    track_folder(g_root);
  }
  return g_root;
}

void plan_root(ChildPlan& plan, const SandboxSpec& spec) {
  plan.root = root_mount_point();
  for (const char* system : {"/usr", "/etc", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"})
    add_mount(plan, system, false);
  for (const char* device : {"/dev/null", "/dev/zero", "/dev/urandom", "/dev/random"}) add_mount(plan, device, true);
  add_special(plan, "/tmp", "tmpfs");
  if (plan.pid_namespace) add_special(plan, "/proc", "proc");
  for (const std::string& path : spec.visible) add_mount(plan, path, false);
  add_mount(plan, spec.work_dir, spec.work_dir_writable);
}

// --- the live programs, for kill_all() -------------------------------------------------------

// The grader builds several runners at once (threads): spawn(), the waits and the search for
// orphans share the list of live programs under this lock, so that a program just started by
// one thread is never taken for an orphan by another.
std::mutex& programs_lock() {
  static std::mutex lock;
  return lock;
}

std::set<pid_t>& live_programs() {
  static std::set<pid_t> programs;
  return programs;
}

void forget(pid_t pid) {
  const std::lock_guard<std::mutex> hold(programs_lock());
  live_programs().erase(pid);
}

// The processes whose parent is the grader and which are not its live programs (call with
// the lock held).
std::vector<pid_t> orphans() {
  std::vector<pid_t> out;
  DIR* proc = opendir("/proc");
  if (!proc) return out;
  const pid_t self = getpid();
  while (const dirent* entry = readdir(proc)) {
    const pid_t pid = static_cast<pid_t>(std::atoi(entry->d_name));
    if (pid <= 0 || live_programs().count(pid)) continue;
    char path[64];
    std::snprintf(path, sizeof path, "/proc/%d/stat", static_cast<int>(pid));
    FILE* file = std::fopen(path, "r");
    if (!file) continue;
    char line[512] = {};
    const bool read = std::fgets(line, sizeof line, file) != nullptr;
    std::fclose(file);
    if (!read) continue;
    // "pid (comm) state ppid ...": comm may hold spaces and parentheses, so read after the last ')'.
    const char* close = std::strrchr(line, ')');
    char state = 0;
    int ppid = 0;
    if (close && std::sscanf(close + 1, " %c %d", &state, &ppid) == 2 && ppid == self) out.push_back(pid);
  }
  closedir(proc);
  return out;
}

// Kills and reaps every process re-parented to the grader that is not a live program of its
// own: what sandboxed programs left behind (detached, double-forked).
void reap_orphans() {
  const std::lock_guard<std::mutex> hold(programs_lock());
  for (int round = 0; round < 1000; ++round) {
    const std::vector<pid_t> stray = orphans();
    for (pid_t pid : stray) kill(pid, SIGKILL);
    for (pid_t pid : stray) waitpid(pid, nullptr, 0);
    if (stray.empty()) return;
  }
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
  if (plan.mount_namespace) plan_root(plan, spec);
  std::fflush(nullptr);
  std::unique_lock<std::mutex> hold(programs_lock());
  const long pid = syscall(SYS_clone, flags | SIGCHLD, nullptr, nullptr, nullptr, nullptr);
  if (pid == 0) child_main(plan);
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
  if (plan.seccomp) {
    // The child's pid as it sees it: 1, the init of its new PID namespace, or the one clone gave.
    std::string failed;
    try {
      const std::vector<sock_filter> filter =
          seccomp_filter((flags & CLONE_NEWPID) ? 1 : static_cast<pid_t>(pid));
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
      kill(static_cast<pid_t>(pid), SIGKILL);
      waitpid(static_cast<pid_t>(pid), nullptr, 0);
      forget(static_cast<pid_t>(pid));
      close(error_pipe[0]);
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

void become_subreaper() {
  prctl(PR_SET_CHILD_SUBREAPER, 1);
  signal(SIGPIPE, SIG_IGN);
}

std::string default_sandbox_user() {
  if (geteuid() != 0) return "";
  if (const char* user = std::getenv("OPSPACE_SANDBOX_USER")) return user;
  return getpwnam("opspace-runner") ? "opspace-runner" : "nobody";
}

std::string describe_wait_status(int status) {
  char buffer[160];
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    std::snprintf(buffer, sizeof buffer, "crashed: %s (signal %d)%s", strsignal(sig), sig,
                  sig == SIGSEGV ? ", e.g. an out-of-range index or a bad pointer"
                  : sig == SIGXCPU ? ": it used up its CPU time"
                  : sig == SIGXFSZ ? ": it wrote a file larger than allowed"
                                   : "");
  } else if (WIFEXITED(status)) {
    std::snprintf(buffer, sizeof buffer, "exited with code %d", WEXITSTATUS(status));
  } else {
    std::snprintf(buffer, sizeof buffer, "ended with status %d", status);
  }
  return buffer;
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
  plan.uid_map = std::to_string(geteuid()) + " " + std::to_string(geteuid()) + " 1";
  plan.gid_map = std::to_string(getegid()) + " " + std::to_string(getegid()) + " 1";

  Protections on;
  if (spec.isolate && spec.user.empty() && geteuid() == 0)
    throw std::invalid_argument("sandbox: a root grader must name the user that runs student code");
  if (spec.isolate && !spec.user.empty() && geteuid() == 0) {
    const passwd* pw = getpwnam(spec.user.c_str());
    if (!pw) throw std::runtime_error("sandbox: no user '" + spec.user + "' on this machine");
    if (pw->pw_uid == 0) throw std::runtime_error("sandbox: user '" + spec.user + "' is root");
    plan.drop_user = true;
    plan.uid = pw->pw_uid;
    plan.gid = pw->pw_gid;
    on.own_user = true;
    plan.limit_processes = true;
  }
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


bool wait_until(const Sandboxed& program, std::chrono::steady_clock::time_point deadline, int& status) {
  auto pause = std::chrono::microseconds(100);
  for (;;) {
    const pid_t done = waitpid(program.pid, &status, WNOHANG);
    if (done == program.pid || (done < 0 && errno == ECHILD)) {
      forget(program.pid);
      reap_orphans();
      return true;
    }
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(5000));
  }
}

void kill_live_programs() {
  const std::lock_guard<std::mutex> hold(programs_lock());
  for (const pid_t pid : live_programs()) {
    kill(-pid, SIGKILL);  // it called setsid(): its group is its own
    kill(pid, SIGKILL);
  }
}

int kill_all(const Sandboxed& program) {
  int status = 0;
  bool live = false;
  {
    const std::lock_guard<std::mutex> hold(programs_lock());
    live = live_programs().count(program.pid) > 0;
  }
  if (live) {
    kill(program.pid, SIGKILL);
    while (waitpid(program.pid, &status, 0) < 0 && errno == EINTR) {
    }
    forget(program.pid);
  }
  reap_orphans();
  return status;
}

}  // namespace opspace::grading
