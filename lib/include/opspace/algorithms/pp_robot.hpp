/// @file algorithms/pp_robot.hpp
/// Closed forms of problem 1a for the PP robot: two prismatic joints d1, d2 along X0, link 2
/// riding on link 1, task x_ee = d1 + d2. These are the oracles of the graded tests; each is
/// derived by hand in problems/1a/guide.md and cross-checked against linalg.hpp in tests/lib.
#pragma once

#include <Eigen/Core>

namespace opspace::pp {

/// Problem set masses (kg).
inline constexpr double kM1 = 10.0;
inline constexpr double kM2 = 5.0;

/// A = [[m1 + m2, m2], [m2, m2]] from T = 1/2 m1 d1dot^2 + 1/2 m2 (d1dot + d2dot)^2.
Eigen::Matrix2d mass_matrix(double m1, double m2);

/// J = [1 1], since x_ee = d1 + d2.
Eigen::RowVector2d task_jacobian();

/// J+ = J^T (J J^T)^-1 = [1/2, 1/2]^T.
Eigen::Vector2d pseudo_inverse();

/// I - J+ J = 1/2 [[1, -1], [-1, 1]].
Eigen::Matrix2d pseudo_inverse_nullspace();

/// J# = W^-1 J^T (J W^-1 J^T)^-1 = [w2, w1]^T / (w1 + w2) for W = diag(w1, w2).
Eigen::Vector2d weighted_inverse(double w1, double w2);

/// I - J# J = [[w1, -w2], [-w1, w2]] / (w1 + w2).
Eigen::Matrix2d weighted_inverse_nullspace(double w1, double w2);

/// Jbar = A^-1 J^T (J A^-1 J^T)^-1 = [0, 1]^T, whatever m1, m2 > 0.
Eigen::Vector2d inertia_weighted_inverse();

/// I - Jbar J = [[1, 0], [-1, 0]].
Eigen::Matrix2d inertia_weighted_nullspace();

}  // namespace opspace::pp
