/// @file grade_problems.hpp
/// The run and judge stages of a grading: each chosen problem's runner, built by the build
/// stage, started in the sandbox; its tests run against it and judged; the library's answers it
/// holds charged to the tests they answer (build/library_answers.hpp). Problems whose runner
/// was not built earn 0 with the reason.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "build/runner_build.hpp"
#include "judge/graded_suite.hpp"
#include "judge/problem_result.hpp"
#include "sandbox/sandbox.hpp"

namespace opspace::grading {

/// How the problems are graded, as the command line set it.
struct GradingSettings {
  bool isolate = true;                     ///< the sandbox (false: debugging only)
  std::map<std::string, double> timeouts;  ///< each chosen problem's limit per test (s), by key
  bool second_runner = true;               ///< a second runner where a core is spare (runs_ahead.hpp)
  unsigned jobs = 1;                       ///< problems graded at once
};

/// The grades in the report's order, and the protections the report states: the first
/// problem's whose runner started.
struct Grades {
  std::vector<ProblemResult> results;
  Protections protections;
  bool started = false;
};

/// Grades `chosen`, whose runners are `built` (same order), with their runners in a folder of
/// /tmp made for this grading, removed after with every process of the grading's account.
/// False, said, if the folder cannot be made.
bool grade_in_run_folder(const std::vector<const Problem*>& chosen, const std::vector<BuiltRunner>& built,
                         const GradingSettings& settings, const Account& account, Grades& grades);

}  // namespace opspace::grading
