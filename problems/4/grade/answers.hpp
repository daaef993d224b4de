/// @file problems/4/grade/answers.hpp
/// The grader's answers to problem 4's functions, named as its contract's (answer::p4::control
/// answers hw2::p4::control): questions i-iv by the library's singularity analysis, the law written
/// out in graded.cpp. grader/suite/grade/reference.cpp gathers every problem's into the grader's Hw2Api
/// (identity 2), which the catalogue of mistakes replays. Trusted: neither the handout nor the
/// Gradescope image keeps this file.
#pragma once

#include "opspace/algorithms/singularity.hpp"

#include "run/api.hpp"

namespace opspace::grading::oracle {

/// 4(v): the law with each target's potential (graded.cpp).
Eigen::Vector3d law_4(hw2::p4::Target target, const hw2::p4::State& s, const hw2::p4::Goal& goal);

namespace answer::p4 {
namespace detail {
inline hw2::p4::Directions first_columns(const Eigen::Matrix3d& U, int first, int count) {
  hw2::p4::Directions d;
  d.count = count;
  d.u.leftCols(count) = U.middleCols(first, count);
  return d;
}
inline Eigen::Matrix<double, 9, 3> stacked(const hw2::p4::Kinematics& k) {
  Eigen::Matrix<double, 9, 3> H;
  H << k.H[0], k.H[1], k.H[2];
  return H;
}
}  // namespace detail
using hw2::p4::Kinematics;
inline const auto degrees_of_freedom = [](const Kinematics& k) { return directions(k.Jv).rank; };
inline const auto singular_directions = [](const Kinematics& k) {
  const Directions3 d = directions(k.Jv);
  return detail::first_columns(d.U, d.rank, 3 - d.rank);
};
inline const auto moving_directions = [](const Kinematics& k) {
  const Directions3 d = directions(k.Jv);
  return detail::first_columns(d.U, 0, d.rank);
};
inline const auto rotation_axes = [](const Kinematics& k) {
  const Directions3 d = directions(k.Jw);
  return detail::first_columns(d.U, 0, d.rank);
};
inline const auto singularity_type = [](const Kinematics& k, const Eigen::Vector3d& u) {
  return opspace::singularity_type(k.Jv, detail::stacked(k), u);
};
inline const auto control = &law_4;
}  // namespace answer::p4

}  // namespace opspace::grading::oracle
