/// @file suite.hpp
/// The graded suite of problem set 2: one function per problem, one file per problem.
#pragma once

#include <string>
#include <vector>

#include "grading.hpp"

namespace opspace::grading {

/// A problem of the set: its key ("1a"), its title, and its graded tests.
struct Problem {
  std::string key;                ///< "1a", "1b", "2", "3" or "4" (hw2-grade --problem KEY)
  std::string title;              ///< printed over its tests
  std::vector<GradedTest> tests;  ///< in the order they are run and reported
};

/// Problem 1a: weighted instantaneous inverse kinematics of the PP robot (p1a.cpp).
Problem problem_1a();

/// Problem 1b: PUMA tip control and null-space motion, in simulation (p1b.cpp).
Problem problem_1b();

/// Problem 2: iiwa position and Euler-parameter tracking, in simulation (p2.cpp).
Problem problem_2();

/// Problem 3: iiwa unified motion and force control against a plane, in simulation (p3.cpp).
Problem problem_3();

/// Problem 4: singularities of the 3R elbow arm, analysed and controlled in simulation (p4.cpp).
Problem problem_4();

/// Every problem, in the order of the problem set.
std::vector<Problem> graded_suite();

}  // namespace opspace::grading
