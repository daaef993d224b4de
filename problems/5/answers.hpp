/// @file problems/5/answers.hpp
/// The grader's answer to problem 5's function, named as its contract's (answer::p5::task_inertia
/// answers hw2::p5::task_inertia): Lambda by a Cholesky solve of A, not an explicit inverse.
/// tests/graded/reference.cpp gathers it into the grader's Hw2Api. Trusted: neither the handout
/// nor the Gradescope image keeps this file.
#pragma once

#include "api.hpp"

namespace opspace::grading::oracle::answer::p5 {
inline const auto task_inertia = [](const Eigen::Matrix2d& J, const Eigen::Matrix2d& A) {
  return Eigen::Matrix2d((J * A.llt().solve(J.transpose())).inverse());
};
}  // namespace opspace::grading::oracle::answer::p5
