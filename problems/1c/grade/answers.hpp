/// @file problems/1c/grade/answers.hpp
/// The grader's answer to problem 1c's function, named as its contract's (answer::p1c::control
/// answers hw2::p1c::control): the law written out in graded.cpp. Trusted: neither the handout nor
/// the Gradescope image keeps this folder.
#pragma once

#include "api.hpp"

namespace opspace::grading::oracle {

/// Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p) (graded.cpp).
hw2::p1c::Vector6d law_1c(const hw2::p1c::State& s, const hw2::p1c::Goal& goal);

namespace answer::p1c {
inline const auto control = &law_1c;
}  // namespace answer::p1c

}  // namespace opspace::grading::oracle
