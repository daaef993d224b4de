/// @file problem_set.hpp
/// Problem 2's desired trajectory as the problem set writes it, independently of the
/// library: what the library tests and the graded suite check problems/2/run/scenario.hpp and 2(a) against.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "opspace/math/constants.hpp"

namespace opspace::testing {

/// The problem set's x_d(t) = [position; lambda_d].
inline Eigen::Matrix<double, 7, 1> problem_set_x_d(double t) {
  const double a = kPi / 4 * std::cos(2 * kPi * t / 5), s = 1 / std::sqrt(2.0);
  Eigen::Matrix<double, 7, 1> x;
  x << 0.0, 0.5 + 0.1 * std::cos(2 * kPi * t / 5), 0.65 - 0.05 * std::cos(4 * kPi * t / 5), s * std::sin(a),
      s * std::cos(a), s * std::sin(a), s * std::cos(a);
  return x;
}

/// The problem set's solution of 2(a), xddot_d(t), term by term.
inline Eigen::Matrix<double, 7, 1> problem_set_xddot_d(double t) {
  const double c = std::cos(2 * kPi * t / 5), sn = std::sin(2 * kPi * t / 5);
  const double sa = std::sin(kPi / 4 * c), ca = std::cos(kPi / 4 * c);
  const double k4 = std::pow(kPi, 4) / (100 * std::sqrt(2.0)), k3 = std::pow(kPi, 3) / (25 * std::sqrt(2.0));
  Eigen::Matrix<double, 7, 1> x;
  x << 0.0, -2 * kPi * kPi / 125 * c, 4 * kPi * kPi / 125 * std::cos(4 * kPi * t / 5),
      -k4 * sa * sn * sn - k3 * ca * c, -k4 * ca * sn * sn + k3 * sa * c, -k4 * sa * sn * sn - k3 * ca * c,
      -k4 * ca * sn * sn + k3 * sa * c;
  return x;
}

}  // namespace opspace::testing
