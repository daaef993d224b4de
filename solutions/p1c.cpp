// Problem 1c, reference solution: the law exactly as the problem set writes it.
#include <opspace/hw2/p1c.hpp>

namespace opspace::hw2::p1c {

// Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p): the tip PD, decoupled, with gravity at the tip
Vector6d control(const State& s, const Goal& goal) {
  const Eigen::Vector3d F = s.Lambda_v * (-goal.kpx * (s.x - goal.x_d) - goal.kvx * s.dx) + s.p;
  return s.Jv.transpose() * F;
}

}  // namespace opspace::hw2::p1c
