/// @file mistakes.hpp
/// The catalogue of known mistakes, one list per problem: the mistakes students make, each as
/// a known-wrong implementation. It serves twice, from one list:
/// - proof: the graded suite must take away exactly the points of the tests aimed at each
///   (tests/mutants/test_graded_suite.cpp);
/// - diagnosis: when a test fails, the grader replays the student's inputs through the
///   reference with each mistake of that test made; the one that reproduces every answer is
///   named in the report ("likely mistake: ...").
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "api.hpp"

namespace opspace::grading {

/// One known mistake.
struct Mistake {
  std::string what;     ///< what was done, as a student would write it
  std::string instead;  ///< what the problem set asks instead, in its words
  /// Makes the mistake in `api`: replaces one or more of its functions by wrappers of the
  /// functions it holds (the reference solutions, or the grader's oracles).
  std::function<void(Hw2Api& api)> apply;
  std::vector<std::string> caught_by;  ///< names of the graded tests that must fail
};

std::vector<Mistake> mistakes_1a();  ///< problem 1a (mistakes_p1a.cpp)
std::vector<Mistake> mistakes_1b();  ///< problem 1b
std::vector<Mistake> mistakes_2();   ///< problem 2
std::vector<Mistake> mistakes_3();   ///< problem 3
std::vector<Mistake> mistakes_4();   ///< problem 4

/// The mistakes of problem `key` ("1a", ... "4"); empty for an unknown key.
std::vector<Mistake> mistakes(const std::string& key);

/// Every known mistake.
std::vector<Mistake> all_mistakes();

}  // namespace opspace::grading
