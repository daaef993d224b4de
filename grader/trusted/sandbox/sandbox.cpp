// The sandbox's public side beside spawn() (sandbox_spawn.cpp): the protections in words, and
// the probe that says whether the sandbox holds whole on this machine.
#include "sandbox/sandbox.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <exception>
#include <string>

#include "common/temporary_folder.hpp"

namespace opspace::grading {

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

bool sandbox_complete(const Account& account, std::string& why) {
  const TemporaryFolder folder("/tmp/opspace-probe-");
  SandboxSpec spec;
  spec.argv = {"/usr/bin/true"};
  spec.work_dir = folder.path();
  spec.account = account;
  Sandboxed program;
  try {
    program = spawn(spec);
  } catch (const std::exception& e) {
    why = e.what();
    return false;
  }
  int status = 0;
  if (!wait_until(program, std::chrono::steady_clock::now() + std::chrono::seconds(30), status)) status = kill_all(program);
  Protections on = program.protections;
  // Without root, the user namespace is the separate identity: no uid of the grader's outside.
  if (geteuid() != 0) on.own_user = on.pid_namespace;
  why = on.missing();
  if (why.empty() && !(WIFEXITED(status) && WEXITSTATUS(status) == 0))
    why = "a trial program " + describe_wait_status(status);
  return why.empty();
}

}  // namespace opspace::grading
