// A submission for problem 1a whose every function spins forever (scripts/regrade's test): the
// grader's per-test time limit stops each test, and the batch goes on meanwhile.
#include <opspace/hw2/p1a.hpp>

namespace opspace::hw2::p1a {

namespace {
// A volatile counter: the compiler may not assume this loop ends.
void spin() {
  volatile unsigned long counter = 0;
  for (;;) counter = counter + 1;
}
}  // namespace

DegreesOfFreedom degrees_of_freedom() { spin(); return {}; }
Eigen::Matrix2d mass_matrix(double, double) { spin(); return {}; }
Eigen::RowVector2d task_jacobian() { spin(); return {}; }
Eigen::Vector2d pseudo_inverse(const Eigen::RowVector2d&) { spin(); return {}; }
Eigen::Vector2d weighted_inverse(const Eigen::RowVector2d&, const Eigen::Matrix2d&) { spin(); return {}; }
Eigen::Vector2d inertia_weighted_inverse(const Eigen::RowVector2d&, const Eigen::Matrix2d&) { spin(); return {}; }
Eigen::Matrix2d nullspace_projector(const Eigen::RowVector2d&, const Eigen::Vector2d&) { spin(); return {}; }
Eigen::Vector2d inverse_kinematics_step(const Eigen::RowVector2d&, const Eigen::Vector2d&, double, const Eigen::Vector2d&) {
  spin();
  return {};
}
DisplacementSplit split_displacement(double, double, double) { spin(); return {}; }

}  // namespace opspace::hw2::p1a
