/// @file diagnosis.hpp
/// Naming a student's mistake: the calls of a test are recorded (run/recording.hpp: arguments
/// and answers, as the protocol encodes them); when the test fails, they are replayed through the grader's
/// reference with each catalogued mistake of that test made (mistakes.hpp). A mistake that
/// reproduces every recorded answer, where the reference does not, is the likely one.
#pragma once

#include <string>
#include <vector>

#include "judge/mistakes.hpp"
#include "run/recording.hpp"

namespace opspace::grading {

/// Whether every answer of `recording` is zero, as the untouched stubs' are (and none is
/// missing): code not written yet, which no known mistake explains.
bool not_written_yet(const Recording& recording);

/// "likely mistake: ...; the problem set asks ..." for the first mistake of `catalogue` aimed at
/// the test whose identity is `test` (GradedTest::id) that reproduces every answer of `recording`
/// (empty if none does).
std::string diagnose(const std::vector<Mistake>& catalogue, const std::string& test, const Recording& recording);

/// Whether the grader's reference with `mistake` made gives every answer of `recording` (true
/// for a recording without calls: it tells nothing). A mistake named by one test that another
/// failed test it is aimed at contradicts is not the student's: two laws may answer alike at
/// the states one test saw and apart at another's.
bool explains(const Mistake& mistake, const Recording& recording);

}  // namespace opspace::grading
