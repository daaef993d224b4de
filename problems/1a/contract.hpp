/// @file problems/1a/contract.hpp
/// (included by its path, <problems/1a/contract.hpp>; the build copies it under the same path for
/// the grader's sandboxed compiler, which sees the contracts and the library's headers only)
/// Problem 1a: weighted instantaneous inverse kinematics of the PP robot.
/// Declared here, written by the student in exercises/p1a.cpp, by the instructor in
/// solutions/p1a.cpp. Two prismatic joints q = (d1, d2) along X0, masses m1 and m2,
/// link 2 riding on link 1; the task is x_ee = d1 + d2.
#pragma once

#include <Eigen/Dense>  // everything a student may need: inverse(), solvers, decompositions

namespace opspace::hw2::p1a {

/// Question i: degrees of freedom of the task and of the robot.
struct DegreesOfFreedom {
  int task = 0;   ///< degrees of freedom of the task (x_ee: 1)
  int robot = 0;  ///< degrees of freedom of the robot (d1, d2: 2)
  bool redundant = false;  ///< the robot has more degrees of freedom than the task needs
};
/// Question i: task DOF = 1 (x_ee), robot DOF = 2 (d1, d2).
DegreesOfFreedom degrees_of_freedom();

/// Question ii: A such that the kinetic energy is T = 1/2 qdot^T A qdot.
Eigen::Matrix2d mass_matrix(double m1, double m2);

/// Question iii: J such that xdot_ee = J qdot.
Eigen::RowVector2d task_jacobian();

/// Question iv: J+ = J^T (J J^T)^-1.
Eigen::Vector2d pseudo_inverse(const Eigen::RowVector2d& J);

/// Question v: J# = W^-1 J^T (J W^-1 J^T)^-1.
Eigen::Vector2d weighted_inverse(const Eigen::RowVector2d& J, const Eigen::Matrix2d& W);

/// Question vi: Jbar = A^-1 J^T (J A^-1 J^T)^-1.
Eigen::Vector2d inertia_weighted_inverse(const Eigen::RowVector2d& J, const Eigen::Matrix2d& A);

/// Questions iv-vi: the null-space projector I - J_inv J of a right inverse J_inv of J.
Eigen::Matrix2d nullspace_projector(const Eigen::RowVector2d& J, const Eigen::Vector2d& J_inv);

/// Questions iv-vi: the family dq = J_inv dx + (I - J_inv J) dq0.
Eigen::Vector2d inverse_kinematics_step(const Eigen::RowVector2d& J, const Eigen::Vector2d& J_inv,
                                        double dx, const Eigen::Vector2d& dq0);

/// Question vi as numbers: how a displacement dx (with dq0 = 0) is shared between the joints.
struct DisplacementSplit {
  Eigen::Vector2d with_pseudo_inverse = Eigen::Vector2d::Zero();       ///< dq = J+ dx
  Eigen::Vector2d with_inertia_weighted = Eigen::Vector2d::Zero();     ///< dq = Jbar dx
};
/// Question vi: dq = J+ dx and dq = Jbar dx for A(m1, m2), with dq0 = 0.
DisplacementSplit split_displacement(double m1, double m2, double dx);

}  // namespace opspace::hw2::p1a
