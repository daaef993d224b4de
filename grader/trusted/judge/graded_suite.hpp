/// @file graded_suite.hpp
/// The graded suite of problem set 2: one function per problem, one file per problem.
#pragma once

#include <string>
#include <vector>

#include "judge/grading.hpp"
#include "protocol/problems.hpp"
#include "run/runs_ahead.hpp"

namespace opspace::grading {

/// A problem of the set: its key ("1a"), its title, and its graded tests.
struct Problem {
  std::string key;                ///< its key in problems.txt, "1a" (hw2-grade --problem KEY)
  std::string title;              ///< printed over its tests
  std::vector<GradedTest> tests;  ///< in the order they are run and reported
  /// Its simulated runs in the order its tests first ask for them, which a second runner may
  /// make ahead (runs_ahead.hpp); empty: each is made by the first test that asks.
  std::vector<ListedRun> runs = {};
};

/// problem_1a() ...: each problem of the list (protocol/problems.hpp) with its graded tests
/// (problems/<key>/grade/graded.cpp; the handout's grader replays them, deploy/handout/replay_suite.cpp).
#define OPSPACE_DECLARE_PROBLEM(key) Problem problem_##key();
OPSPACE_PROBLEM_KEYS(OPSPACE_DECLARE_PROBLEM)
#undef OPSPACE_DECLARE_PROBLEM

/// Every problem, in the list's order.
std::vector<Problem> graded_suite();

}  // namespace opspace::grading
