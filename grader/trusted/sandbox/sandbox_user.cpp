// Who the sandboxed program is. Two mechanisms, by what the grader is:
// - as root, it switches to an unprivileged account, groups first, then the user, so that the
//   program can neither signal the grader's processes nor read root's files, and its process
//   limit counts only that account's processes. By default the account is the grading's own
//   (grading_account()): a uid of a range no account uses, held by a lock file for as long as
//   the grader lives, so that gradings running at once (scripts/regrade --jobs) never share
//   one: none can signal, read or write what another's student code owns, or fill its process
//   limit. --sandbox-user names a shared account instead (opspace-runner, nobody);
// - in a user namespace (an unprivileged grader), it maps its own ids onto themselves: the
//   namespace's capabilities, which the mounts need, then go away at execve(), since its uid
//   there is not 0.
#include <fcntl.h>
#include <pwd.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <string>

#include "sandbox/sandbox_plan.hpp"

namespace opspace::grading {

namespace sandbox_internal {

namespace {

bool write_file(const char* path, const char* text) {
  const int fd = open(path, O_WRONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const std::size_t size = std::strlen(text);
  const bool ok = write(fd, text, size) == static_cast<ssize_t>(size);
  close(fd);
  return ok;
}

}  // namespace

void plan_user(ChildPlan& plan, const SandboxSpec& spec, Protections& on) {
  plan.uid_map = std::to_string(geteuid()) + " " + std::to_string(geteuid()) + " 1";
  plan.gid_map = std::to_string(getegid()) + " " + std::to_string(getegid()) + " 1";
  if (spec.isolate && spec.account.uid == 0 && geteuid() == 0)
    throw std::invalid_argument("sandbox: a root grader must name the account that runs student code");
  if (spec.isolate && spec.account.uid != 0 && geteuid() == 0) {
    plan.drop_user = true;
    plan.uid = spec.account.uid;
    plan.gid = spec.account.gid;
    on.own_user = true;
    plan.limit_processes = true;
  }
}

void child_map_ids(const ChildPlan& plan) {
  // Map our own ids into the new user namespace: execve then drops the capabilities this
  // process holds there, since its uid is not 0.
  if (!write_file("/proc/self/uid_map", plan.uid_map.c_str())) child_fail(plan, "map the user id");
  if (!write_file("/proc/self/setgroups", "deny")) child_fail(plan, "deny setgroups");
  if (!write_file("/proc/self/gid_map", plan.gid_map.c_str())) child_fail(plan, "map the group id");
}

void child_drop_user(const ChildPlan& plan) {
  // Raw system calls: the C library's wrappers would wait for the grader's other threads,
  // which do not exist in this process.
  if (syscall(SYS_setgroups, 0, nullptr) != 0) child_fail(plan, "drop the supplementary groups");
  if (syscall(SYS_setresgid, plan.gid, plan.gid, plan.gid) != 0) child_fail(plan, "change group");
  if (syscall(SYS_setresuid, plan.uid, plan.uid, plan.uid) != 0) child_fail(plan, "change user");
  if (syscall(SYS_setuid, 0) == 0) child_fail(plan, "the user change did not hold");
}

}  // namespace sandbox_internal

namespace {

// The range of the gradings' own uids: above every account Debian allocates (its dynamic
// users end at 65519), one per grading running at once.
constexpr uid_t kFirstOwnUid = 3500000;
constexpr uid_t kOwnUids = 1000;

// Whether the kernel maps uids [first, first + count) in this user namespace (a container
// with a user namespace of its own maps fewer: setresuid would fail there).
bool mapped(uid_t first, uid_t count) {
  std::ifstream map("/proc/self/uid_map");
  unsigned long long inside = 0, outside = 0, length = 0;
  while (map >> inside >> outside >> length)
    if (inside <= first && first + count <= inside + length) return true;
  return false;
}

// The folder of the uids' lock files: root's alone (another owner or a writable folder could
// hand out a uid twice).
std::string lock_folder() {
  const std::string dir = access("/run", W_OK) == 0 ? "/run/opspace-grader" : "/tmp/opspace-grader-uids";
  if (mkdir(dir.c_str(), 0700) != 0 && errno != EEXIST) return "";
  struct stat s {};
  if (lstat(dir.c_str(), &s) != 0 || !S_ISDIR(s.st_mode) || s.st_uid != 0 || (s.st_mode & 077) != 0) return "";
  return dir;
}

Account named_account(const std::string& name) {
  const passwd* pw = getpwnam(name.c_str());
  if (!pw) throw std::runtime_error("sandbox: no user '" + name + "' on this machine");
  if (pw->pw_uid == 0) throw std::runtime_error("sandbox: user '" + name + "' is root");
  return Account{pw->pw_uid, pw->pw_gid, name, false};
}

}  // namespace

Account grading_account(const std::string& named) {
  if (geteuid() != 0) return {};
  if (!named.empty()) return named_account(named);
  static std::mutex lock;
  static Account own;
  const std::lock_guard<std::mutex> hold(lock);
  if (own.uid != 0) return own;
  const std::string dir = mapped(kFirstOwnUid, kOwnUids) ? lock_folder() : "";
  for (uid_t uid = kFirstOwnUid; !dir.empty() && uid < kFirstOwnUid + kOwnUids; ++uid) {
    // Held, not closed, until the grader ends: the kernel releases the lock with it, even after
    // a SIGKILL.
    const int fd = open((dir + "/uid-" + std::to_string(uid) + ".lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
    if (fd < 0) break;
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
      close(fd);
      continue;
    }
    own = Account{uid, static_cast<gid_t>(uid), "uid " + std::to_string(uid) + " (this grading's own)", true};
    kill_account(own);  // what a grading before this one, killed, may have left
    return own;
  }
  return named_account(getpwnam("opspace-runner") ? "opspace-runner" : "nobody");
}

void kill_account(const Account& account) {
  if (!account.own || account.uid == 0 || geteuid() != 0) return;
  const pid_t helper = fork();
  if (helper == 0) {
    // The helper becomes the account (a signal needs the sender's uid to be the target's), then
    // signals every process it may: exactly the account's (kill(-1) spares the sender).
    if (syscall(SYS_setgroups, 0, nullptr) != 0 || syscall(SYS_setresgid, account.gid, account.gid, account.gid) != 0 ||
        syscall(SYS_setresuid, account.uid, account.uid, account.uid) != 0)
      _exit(1);
    kill(-1, SIGKILL);
    _exit(0);
  }
  if (helper > 0) waitpid(helper, nullptr, 0);
}

}  // namespace opspace::grading
