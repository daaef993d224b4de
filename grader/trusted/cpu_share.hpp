/// @file cpu_share.hpp
/// Gradings running at once (scripts/regrade --jobs N) share the CPU equally, however many
/// processes one student's code starts: each grader puts itself, and so everything it starts
/// (compilers, runners), in a CPU cgroup of its own, where the kernel offers a writable one
/// (cgroup v1's cpu controller; cgroup v2 where the grader sits at the root of its hierarchy).
/// The scheduler then divides the CPU between the gradings' groups, not between their
/// processes. Where none is offered, a test's limit in the runner's CPU time still keeps an
/// honest runner in time (runner_process.hpp).
#pragma once

#include <string>

namespace opspace::grading {

/// Moves this process into a CPU cgroup of its own (call before any thread or child starts);
/// removes the groups of earlier graders that have ended. Returns where ("cgroup v1
/// cpu:/opspace-grading-42"), or empty where no writable cgroup is offered. The group is left
/// and removed when the process exits.
std::string join_own_cpu_group();

}  // namespace opspace::grading
