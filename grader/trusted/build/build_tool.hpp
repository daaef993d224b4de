/// @file build_tool.hpp
/// A tool of the runner's build (the compiler, the linker, nm) run in the sandbox on the
/// student's file: its output captured up to a limit, within the build's time limit.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "sandbox/sandbox.hpp"

namespace opspace::grading {

/// Where and how to build.
struct BuildSettings {
  std::string cache_dir;   ///< built runners are kept here, by the hash of their inputs (the grader's alone)
  Account account;         ///< when the grader is root: the account that compiles
  bool isolate = true;     ///< the sandbox (false: debugging only)
  double timeout = 180.0;  ///< seconds for each of compiling and linking
};

/// What a tool did.
struct ToolResult {
  bool timed_out = false;
  int status = 0;      ///< its wait status
  std::string output;  ///< stdout and stderr, at most the limit given to run_tool
  bool cut = false;    ///< the output was longer than that
  std::size_t total = 0;  ///< how many bytes it wrote in all (read to its end, or to the deadline)
};

/// Runs `argv` in the sandbox as `settings` says, within settings.timeout, keeping at most
/// `max_output` bytes of what it writes. It sees the system's folders, `visible` (read-only)
/// and `work_dir`, the only folder it may write (owned by the sandbox's account).
ToolResult run_tool(const std::vector<std::string>& argv, const std::string& work_dir,
                    const std::vector<std::string>& visible, const BuildSettings& settings, std::size_t max_output);

}  // namespace opspace::grading
