// Problem 1a, reference solution: weighted instantaneous inverse kinematics of the PP robot.
#include <problems/1a/contract.hpp>

namespace opspace::hw2::p1a {

DegreesOfFreedom degrees_of_freedom() {
  // The task is one coordinate (x_ee); the robot has two joints (d1, d2).
  DegreesOfFreedom dof;
  dof.task = 1;
  dof.robot = 2;
  dof.redundant = dof.robot > dof.task;
  return dof;
}

Eigen::Matrix2d mass_matrix(double m1, double m2) {
  // T = 1/2 (m1 + m2) d1dot^2 + m2 d1dot d2dot + 1/2 m2 d2dot^2
  Eigen::Matrix2d A;
  A << m1 + m2, m2,
       m2,      m2;
  return A;
}

Eigen::RowVector2d task_jacobian() {
  // x_ee = d1 + d2
  return Eigen::RowVector2d(1.0, 1.0);
}

Eigen::Vector2d pseudo_inverse(const Eigen::RowVector2d& J) {
  // J J^T is 1x1: a scalar
  return J.transpose() / J.squaredNorm();
}

Eigen::Vector2d weighted_inverse(const Eigen::RowVector2d& J, const Eigen::Matrix2d& W) {
  const Eigen::Vector2d Winv_Jt = W.inverse() * J.transpose();
  return Winv_Jt / J.dot(Winv_Jt);
}

Eigen::Vector2d inertia_weighted_inverse(const Eigen::RowVector2d& J, const Eigen::Matrix2d& A) {
  // The weighted inverse with the mass matrix as the weight.
  return weighted_inverse(J, A);
}

Eigen::Matrix2d nullspace_projector(const Eigen::RowVector2d& J, const Eigen::Vector2d& J_inv) {
  return Eigen::Matrix2d::Identity() - J_inv * J;
}

Eigen::Vector2d inverse_kinematics_step(const Eigen::RowVector2d& J, const Eigen::Vector2d& J_inv,
                                        double dx, const Eigen::Vector2d& dq0) {
  return J_inv * dx + nullspace_projector(J, J_inv) * dq0;
}

DisplacementSplit split_displacement(double m1, double m2, double dx) {
  const Eigen::RowVector2d J = task_jacobian();
  const Eigen::Vector2d no_self_motion = Eigen::Vector2d::Zero();
  DisplacementSplit split;
  split.with_pseudo_inverse = inverse_kinematics_step(J, pseudo_inverse(J), dx, no_self_motion);
  split.with_inertia_weighted =
      inverse_kinematics_step(J, inertia_weighted_inverse(J, mass_matrix(m1, m2)), dx, no_self_motion);
  return split;
}

}  // namespace opspace::hw2::p1a
