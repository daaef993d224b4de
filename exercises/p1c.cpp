// Problem 1c: the PUMA 560 holds its tip with the tip PD and no joint damping.
// Run:    bash scripts/run hw2-p1c
// Grade:  bash scripts/grade --problem 1c
//
// `s` holds what the robot knows now (problem 1b's State): the tip s.x, s.dx, its Jacobian
// s.Jv, the mass matrix s.A, gravity s.g, and the task quantities s.Lambda_v, s.Jbar_v, s.p.
// `goal` holds x_d and the gains kpx, kvx.
#include <opspace/hw2/p1c.hpp>

namespace opspace::hw2::p1c {

Vector6d control(const State& s, const Goal& goal) {
  // Hold the tip at x_d; nothing damps the joints:
  //   Gamma = Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p)
  // FILL ME IN
  return Vector6d::Zero();
}

}  // namespace opspace::hw2::p1c
