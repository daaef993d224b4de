// Problem 5: the task inertia of a planar 2R arm's tip.
// Grade your work with:  bash scripts/grade --problem 5
#include <opspace/hw2/p5.hpp>

namespace opspace::hw2::p5 {

// The task inertia  Lambda = (J A^-1 J^T)^-1
Eigen::Matrix2d task_inertia(const Eigen::Matrix2d& J, const Eigen::Matrix2d& A) {
  // FILL ME IN
  return Eigen::Matrix2d::Zero();
}

}  // namespace opspace::hw2::p5
