/// @file problems/1b/grade/answers.hpp
/// The grader's answers to problem 1b's functions, named as its contract's (answer::p1b::control
/// answers hw2::p1b::control): the law written out in graded.cpp. grader/suite/grade/reference.cpp
/// gathers every problem's into the grader's Hw2Api (identity 2), which the catalogue of mistakes
/// replays. Trusted: neither the handout nor the Gradescope image keeps this file.
#pragma once

#include "run/api.hpp"

namespace opspace::grading::oracle {

/// The torque of `part` (graded.cpp).
hw2::p1b::Vector6d law_1b(hw2::p1b::Part part, const hw2::p1b::State& s, const hw2::p1b::Goal& goal);

namespace answer::p1b {
inline const auto control = &law_1b;
}  // namespace answer::p1b

}  // namespace opspace::grading::oracle
