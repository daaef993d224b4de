/// @file problems/3/grade/answers.hpp
/// The grader's answers to problem 3's functions, named as its contract's (answer::p3::control
/// answers hw2::p3::control): Omega, Omega-bar and the law written out in graded.cpp.
/// grader/suite/grade/reference.cpp gathers every problem's into the grader's Hw2Api (identity 2), which
/// the catalogue of mistakes replays. Trusted: neither the handout nor the Gradescope image keeps
/// this file.
#pragma once

#include "run/api.hpp"

namespace opspace::grading::oracle {

/// 3(a): Omega and Omega-bar (graded.cpp).
hw2::p3::Matrix6d omega();
hw2::p3::Matrix6d omega_bar();
/// 3(b): the unified motion and force law (graded.cpp).
hw2::p3::Vector7d law_3(const hw2::p3::State& s, const hw2::p3::Goal& goal);

namespace answer::p3 {
inline const auto motion_selection = &omega;
inline const auto force_selection = &omega_bar;
inline const auto control = &law_3;
}  // namespace answer::p3

}  // namespace opspace::grading::oracle
