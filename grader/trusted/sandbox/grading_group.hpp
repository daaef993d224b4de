/// @file grading_group.hpp
/// Each grading's share of the machine, as one unit. Gradings running at once (scripts/regrade
/// --jobs N) share it as Gradescope's containers do, however many processes or bytes one
/// student's code asks for:
///   - the CPU: the grader puts itself, and so everything it starts, in a CPU cgroup of its own
///     (cgroup v1's cpu controller; cgroup v2 where the grader sits at the root of its view);
///     the scheduler then divides the CPU between gradings, not between their processes;
///   - memory and processes: every program the grader starts (compiler, linker, nm, runners) is
///     put in a group of this grading's own with memory.max (v1: memory.limit_in_bytes) and
///     pids.max; the private /tmp of each is memory too, so it counts. The grader itself stays
///     out, so that the kernel, at the budget, stops the student's program, never the grader.
/// Where no writable group is offered (not root, or no such controller), each tool's address
/// space is capped at the budget instead (build_tool.cpp), and a test's limit counts the
/// runner's CPU time (runner_process.hpp).
#pragma once

#include <sys/types.h>

#include <string>

namespace opspace::grading {

/// What one grading may use of the machine.
struct GradingBudget {
  unsigned long long memory_bytes = 0;  ///< all its programs together (0: no budget)
  unsigned long long processes = 0;     ///< all its programs' processes and threads together (0: none)
};

/// Where the grading's groups are, said in --check-sandbox (empty parts: none offered).
struct GradingGroups {
  std::string cpu;     ///< "cgroup v1 cpu:/opspace-grading-42"
  std::string memory;  ///< "cgroup v1 memory:/opspace-grading-42, 1024 MiB"
  std::string pids;    ///< "cgroup v1 pids:/opspace-grading-42, 512"
};

/// Puts this process in a CPU group of its own and makes its programs' memory and process
/// groups (call before any thread or child starts); removes the groups of graders that have
/// ended. The groups are left and removed when the process exits. Not root: no group, and the
/// budget caps each program's address space (address_space_within_budget).
GradingGroups join_grading_groups(const GradingBudget& budget);

/// Puts a program the grader has just started (and so all it starts) in the grading's memory
/// and process groups; does nothing where there are none.
void admit_to_grading_groups(pid_t pid);

/// How many times the kernel has stopped a program of this grading at its memory budget (0
/// where there is no memory group): read before and after a program runs, a change names the
/// budget as the reason a program was killed.
unsigned long long grading_memory_kills();

/// The memory budget a group enforces (0: none, each tool's address space holds it instead).
unsigned long long grading_memory_group_budget();

/// A program's address-space limit within the budget: `own` where a group enforces the budget
/// (or there is none) and where `own` is 0 (no limit), else the smaller of `own` and the budget.
unsigned long long address_space_within_budget(unsigned long long own);

/// The machine's memory (bytes), the default budget of a grading that runs alone.
unsigned long long machine_memory();

/// What a grading may use: `memory_mib` (--memory), else the machine's memory; processes for the
/// builds running at once (one per core, each under its account's 64, build_tool.cpp) and as
/// many runners (16 each, runner_process.cpp).
GradingBudget grading_budget(unsigned long long memory_mib);

}  // namespace opspace::grading
