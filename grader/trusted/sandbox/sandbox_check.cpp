#include "sandbox/sandbox_check.hpp"

#include <iostream>

namespace opspace::grading {

namespace {

// Why the code graded would run with this grader's rights here, in words for the report; empty
// where the sandbox holds whole. `missing` names what the sandbox lacks when it is incomplete.
std::string unprotected_reason(const SandboxWish& wish, const Account& account, std::string& missing) {
  if (!wish.isolate) return "the sandbox is off (--no-isolation)";
  if (sandbox_complete(account, missing)) return "";
  return "the sandbox is incomplete here (missing: " + missing + ")";
}

}  // namespace

bool may_grade_here(const SandboxWish& wish, const Account& account, const char* program, std::string& unprotected) {
  std::string missing;
  unprotected = unprotected_reason(wish, account, missing);
  if (missing.empty() || wish.allow_unprotected || wish.check_only) return true;
  std::cerr << program << ": refused: the sandbox cannot be built here (missing: " << missing
            << "), so the code graded would run with this grader's rights. Grade your own files with "
               "--unprotected (scripts/grade does); grade others' only where the sandbox holds (docs/grader.md)\n";
  return false;
}

int print_sandbox_check(const GradingGroups& groups, const std::string& unprotected) {
  std::cout << (unprotected.empty() ? "sandbox: complete" : "sandbox: " + unprotected) << "\n"
            << "cpu share: "
            << (groups.cpu.empty() ? "no writable cgroup here: each test's limit counts the runner's CPU time"
                                   : "a group per grading, " + groups.cpu)
            << "\nmemory budget: "
            << (groups.memory.empty() ? "no writable memory cgroup here: each program's address space is capped"
                                      : "a group per grading, " + groups.memory)
            << "\nprocess budget: "
            << (groups.pids.empty() ? "no writable pids cgroup here: each program's account limits its processes"
                                    : "a group per grading, " + groups.pids)
            << "\n";
  return unprotected.empty() ? 0 : kExitUnprotected;
}

}  // namespace opspace::grading
