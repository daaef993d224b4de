// Problem 5: the task inertia of a planar 2R arm's tip (reference solution).
#include <opspace/hw2/p5.hpp>

namespace opspace::hw2::p5 {

// The task inertia  Lambda = (J A^-1 J^T)^-1
Eigen::Matrix2d task_inertia(const Eigen::Matrix2d& J, const Eigen::Matrix2d& A) {
  return (J * A.inverse() * J.transpose()).inverse();
}

}  // namespace opspace::hw2::p5
