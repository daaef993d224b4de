/// @file problem_result.hpp
/// A problem graded: every test's result, with the points earned and available, and what the
/// student should know beside them. Every report is written from these.
#pragma once

#include <string>
#include <vector>

#include "judge/graded_suite.hpp"

namespace opspace::grading {

/// The results of one problem's tests, with the points earned and available.
struct ProblemResult {
  const Problem* problem = nullptr;  ///< the problem graded
  std::vector<TestResult> results;   ///< one per test, in the problem's order
  double score = 0.0;                ///< sum of the results' scores
  double max_score = 0.0;            ///< sum of the tests' points
  std::string failure;   ///< empty, or why the problem could not be graded (its file does not compile)
  bool grader_fault = false;  ///< `failure` is the grader's own (fault.hpp), not the submission's
  std::string warnings;  ///< the compiler's warnings on the problem's file (shown, never fatal)
  std::vector<std::string> notes;  ///< other things the student should know (oracle calls)
};

/// Points as the report and the grader's notes write them ("%g": 3, 2.5, 0.25).
std::string format_points(double value);

/// Runs every test of `problem` against `api`.
ProblemResult grade(const Problem& problem, const Hw2Api& api);

}  // namespace opspace::grading
