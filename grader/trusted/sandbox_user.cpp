// Who the sandboxed program is. Two mechanisms, by what the grader is:
// - as root, it switches to an unprivileged user (--sandbox-user; default_sandbox_user() is
//   OPSPACE_SANDBOX_USER, "opspace-runner" or "nobody"), groups first, then the user, so that
//   the program can neither signal the grader's processes nor read root's files, and its
//   process limit counts only that user's processes;
// - in a user namespace (an unprivileged grader), it maps its own ids onto themselves: the
//   namespace's capabilities, which the mounts need, then go away at execve(), since its uid
//   there is not 0.
#include <fcntl.h>
#include <pwd.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include "sandbox_plan.hpp"

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

std::string default_sandbox_user() {
  if (geteuid() != 0) return "";
  if (const char* user = std::getenv("OPSPACE_SANDBOX_USER")) return user;
  return getpwnam("opspace-runner") ? "opspace-runner" : "nobody";
}

}  // namespace opspace::grading
