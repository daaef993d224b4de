// Problem 1a: weighted instantaneous inverse kinematics of the PP robot.
// q = (d1, d2): two prismatic joints along X0; link 2 (mass m2) rides on link 1 (mass m1).
// The task is the end-effector displacement along X0: x_ee = d1 + d2.
// Grade your work with:  bash scripts/grade --problem 1a
#include <problems/1a/contract.hpp>

namespace opspace::hw2::p1a {

// i. How many degrees of freedom does the task need, how many does the robot have,
//    and is the robot redundant with respect to the task?
DegreesOfFreedom degrees_of_freedom() {
  DegreesOfFreedom dof;
  // FILL ME IN
  return dof;
}

// ii. The mass matrix A, read off the kinetic energy
//       T = 1/2 m1 d1dot^2 + 1/2 m2 (d1dot + d2dot)^2 = 1/2 qdot^T A qdot
Eigen::Matrix2d mass_matrix(double m1, double m2) {
  // FILL ME IN
  return Eigen::Matrix2d::Zero();
}

// iii. The task Jacobian J:  xdot_ee = J qdot
Eigen::RowVector2d task_jacobian() {
  // FILL ME IN
  return Eigen::RowVector2d::Zero();
}

// iv. The pseudo-inverse  J+ = J^T (J J^T)^-1
Eigen::Vector2d pseudo_inverse(const Eigen::RowVector2d& J) {
  // FILL ME IN
  return Eigen::Vector2d::Zero();
}

// v. The weighted inverse  J# = W^-1 J^T (J W^-1 J^T)^-1
Eigen::Vector2d weighted_inverse(const Eigen::RowVector2d& J, const Eigen::Matrix2d& W) {
  // FILL ME IN
  return Eigen::Vector2d::Zero();
}

// vi. The inertia-weighted (dynamically consistent) inverse  Jbar = A^-1 J^T (J A^-1 J^T)^-1
Eigen::Vector2d inertia_weighted_inverse(const Eigen::RowVector2d& J, const Eigen::Matrix2d& A) {
  // FILL ME IN
  return Eigen::Vector2d::Zero();
}

// iv-vi. The null-space projector of a right inverse J_inv of J:  I - J_inv J
Eigen::Matrix2d nullspace_projector(const Eigen::RowVector2d& J, const Eigen::Vector2d& J_inv) {
  // FILL ME IN
  return Eigen::Matrix2d::Zero();
}

// iv-vi. The family of instantaneous inverse-kinematic solutions:
//          dq = J_inv dx + (I - J_inv J) dq0
Eigen::Vector2d inverse_kinematics_step(const Eigen::RowVector2d& J, const Eigen::Vector2d& J_inv,
                                        double dx, const Eigen::Vector2d& dq0) {
  // FILL ME IN
  return Eigen::Vector2d::Zero();
}

// vi. With dq0 = 0, how is a displacement dx shared between d1 and d2?
//       with_pseudo_inverse   = J+ dx     (J+ of the task Jacobian)
//       with_inertia_weighted = Jbar dx   (Jbar with W = A(m1, m2))
//     Use your functions above.
DisplacementSplit split_displacement(double m1, double m2, double dx) {
  DisplacementSplit split;
  // FILL ME IN
  return split;
}

}  // namespace opspace::hw2::p1a
