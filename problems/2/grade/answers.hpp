/// @file problems/2/grade/answers.hpp
/// The grader's answers to problem 2's functions, named as its contract's (answer::p2::control
/// answers hw2::p2::control): 2(a) and 2(b) as the problem set writes them, the law written out in
/// graded.cpp. grader/suite/grade/reference.cpp gathers every problem's into the grader's Hw2Api
/// (identity 2), which the catalogue of mistakes replays. Trusted: neither the handout nor the
/// Gradescope image keeps this file.
#pragma once

#include "opspace/algorithms/euler_params.hpp"

#include "run/api.hpp"
#include <problems/2/problem_set.hpp>

namespace opspace::grading::oracle {

/// 2(c): the tracking law (graded.cpp).
hw2::p2::Vector7d law_2(const hw2::p2::State& s, const hw2::p2::Goal& goal);

namespace answer::p2 {
inline const auto desired_acceleration = &testing::problem_set_xddot_d;
inline const auto desired_twist_acceleration = [](const Eigen::Vector4d& lambda, const hw2::p2::Vector7d& xddot_d) {
  return hw2::p2::Vector6d(representation_matrix_pinv(lambda) * xddot_d);
};
inline const auto control = &law_2;
}  // namespace answer::p2

}  // namespace opspace::grading::oracle
