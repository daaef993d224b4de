// The sandboxed program's resource limits (sandbox.hpp's Limits), set by setrlimit() in the
// child before it drops its privileges: caps on memory, CPU time, file size, open files and,
// when it runs as a user of its own (RLIMIT_NPROC counts a user's processes), processes, so
// that a runaway submission ends with a signal the grader can name (describe_wait_status())
// instead of taking the machine with it. No core files: a crashing program writes nothing. A
// limit of 0 is left as it is.
#include <sys/resource.h>

#include "sandbox/sandbox_plan.hpp"

namespace opspace::grading::sandbox_internal {

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

}  // namespace opspace::grading::sandbox_internal
