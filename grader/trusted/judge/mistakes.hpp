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

#include "run/api.hpp"

namespace opspace::grading {

/// One known mistake.
struct Mistake {
  std::string what;     ///< what was done, as a student would write it
  std::string instead;  ///< what the problem set asks instead, in its words
  /// Makes the mistake in `api`: replaces one or more of its functions by wrappers of the
  /// functions it holds (the reference solutions, or the grader's oracles).
  std::function<void(Hw2Api& api)> apply;
  std::vector<std::string> caught_by;  ///< identities of the graded tests that must fail (GradedTest::id)
};

/// mistakes_1a() ...: each problem's mistakes (problems/<key>/grade/mistakes.cpp), one per
/// problem of the list (protocol/problems.hpp).
#define OPSPACE_DECLARE_MISTAKES(key) std::vector<Mistake> mistakes_##key();
OPSPACE_PROBLEM_KEYS(OPSPACE_DECLARE_MISTAKES)
#undef OPSPACE_DECLARE_MISTAKES

/// The mistakes of problem `key` ("1a", ...); empty for an unknown key.
std::vector<Mistake> mistakes(const std::string& key);

/// Every known mistake.
std::vector<Mistake> all_mistakes();

}  // namespace opspace::grading
