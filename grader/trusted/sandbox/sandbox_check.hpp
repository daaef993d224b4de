/// @file sandbox_check.hpp
/// Whether the sandbox holds whole where the grader runs, before anyone's code is compiled or
/// run: where it cannot (no namespaces), the code graded would run with the grader's rights,
/// next to other students' files and grades. Only an explicit --unprotected grades there, and
/// every report says so.
#pragma once

#include <string>

#include "sandbox/grading_group.hpp"
#include "sandbox/sandbox.hpp"

namespace opspace::grading {

/// The exit code of a grader that refused to run code where the sandbox cannot be built.
constexpr int kExitUnprotected = 3;

/// What the command line asked of the sandbox.
struct SandboxWish {
  bool isolate = true;             ///< the sandbox (false: --no-isolation)
  bool allow_unprotected = false;  ///< --unprotected
  bool check_only = false;         ///< --check-sandbox
};

/// Whether the grader may grade here. `unprotected` is set to why the code graded would run
/// with this grader's rights (empty where the sandbox holds whole); false, said on stderr by
/// `program`, where the grader refuses.
bool may_grade_here(const SandboxWish& wish, const Account& account, const char* program, std::string& unprotected);

/// --check-sandbox: what holds here, the sandbox and each of the grading's groups, on stdout;
/// 0 if whole, else kExitUnprotected.
int print_sandbox_check(const GradingGroups& groups, const std::string& unprotected);

}  // namespace opspace::grading
