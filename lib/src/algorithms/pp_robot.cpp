#include "opspace/algorithms/pp_robot.hpp"

namespace opspace::pp {

Eigen::Matrix2d mass_matrix(double m1, double m2) {
  return (Eigen::Matrix2d() << m1 + m2, m2, m2, m2).finished();
}

Eigen::RowVector2d task_jacobian() { return Eigen::RowVector2d(1.0, 1.0); }

Eigen::Vector2d pseudo_inverse() { return Eigen::Vector2d(0.5, 0.5); }

Eigen::Matrix2d pseudo_inverse_nullspace() {
  return 0.5 * (Eigen::Matrix2d() << 1.0, -1.0, -1.0, 1.0).finished();
}

Eigen::Vector2d weighted_inverse(double w1, double w2) {
  return Eigen::Vector2d(w2, w1) / (w1 + w2);
}

Eigen::Matrix2d weighted_inverse_nullspace(double w1, double w2) {
  return (Eigen::Matrix2d() << w1, -w2, -w1, w2).finished() / (w1 + w2);
}

Eigen::Vector2d inertia_weighted_inverse() { return Eigen::Vector2d(0.0, 1.0); }

Eigen::Matrix2d inertia_weighted_nullspace() {
  return (Eigen::Matrix2d() << 1.0, 0.0, -1.0, 0.0).finished();
}

}  // namespace opspace::pp
