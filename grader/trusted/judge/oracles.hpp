/// @file oracles.hpp
/// The grader's own answers, the ones its tests compare with, gathered as a Hw2Api
/// (grader/suite/grade/reference.cpp): each problem's are in its folder (problems/<key>/grade/answers.hpp,
/// with the laws its graded.cpp writes out from the library's quantities). The catalogue of
/// mistakes (mistakes.hpp) replays a student's inputs through this api with one mistake made,
/// to name the mistake a student made.
#pragma once

#include "run/api.hpp"

namespace opspace::grading::oracle {

/// Every function of the problem set, answered by the grader's oracles. Identity 2.
Hw2Api reference_api();

}  // namespace opspace::grading::oracle
