// Runs a command where no namespace can be made, as in a container whose seccomp profile
// forbids them (Docker's default without CAP_SYS_ADMIN) or on a host without user namespaces:
// unshare() and setns() fail with EPERM, clone() with any CLONE_NEW* flag too, and clone3()
// with ENOSYS (so that the C library falls back to clone()). The filter is inherited by
// everything the command starts.
//   deny_namespaces PROGRAM [ARGUMENTS...]
#include <sched.h>
#include <seccomp.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: deny_namespaces PROGRAM [ARGUMENTS...]\n");
    return 2;
  }
  scmp_filter_ctx context = seccomp_init(SCMP_ACT_ALLOW);
  if (!context) return 1;
  const scmp_datum_t namespaces =
      CLONE_NEWNS | CLONE_NEWPID | CLONE_NEWNET | CLONE_NEWUSER | CLONE_NEWIPC | CLONE_NEWUTS | CLONE_NEWCGROUP;
  scmp_arg_cmp any_namespace{};
  any_namespace.arg = 0;
  any_namespace.op = SCMP_CMP_MASKED_EQ;
  any_namespace.datum_a = namespaces;
  bool ok = seccomp_rule_add(context, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(unshare), 0) == 0 &&
            seccomp_rule_add(context, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(setns), 0) == 0 &&
            seccomp_rule_add(context, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0) == 0;
  // MASKED_EQ compares (arg & mask) == datum: one rule per flag, each "this flag is set".
  for (scmp_datum_t flag = 1; ok && flag != 0; flag <<= 1) {
    if (!(namespaces & flag)) continue;
    any_namespace.datum_a = flag;
    any_namespace.datum_b = flag;
    ok = seccomp_rule_add_array(context, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(clone), 1, &any_namespace) == 0;
  }
  ok = ok && seccomp_load(context) == 0;
  seccomp_release(context);
  if (!ok) {
    std::fprintf(stderr, "deny_namespaces: could not install the filter\n");
    return 1;
  }
  execvp(argv[1], argv + 1);
  std::perror("deny_namespaces: execvp");
  return 127;
}
