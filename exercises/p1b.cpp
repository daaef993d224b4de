// Problem 1b: the PUMA 560 holds its tip still while joint 2 moves in the null space.
// Run:    bash scripts/run hw2-p1 1        (or 2, 3; add --no-joint-damping to part 1)
// Grade:  bash scripts/grade --problem 1b
//
// `s` holds what the robot knows now: s.q, s.dq, the tip s.x, s.dx, its Jacobian s.Jv,
// the mass matrix s.A, gravity s.g, and the task quantities s.Lambda_v, s.Jbar_v, s.p.
// `goal` holds x_d, q_d and the gains kpx, kvx, kpj, kvj.
// opspace::pseudo_inverse(Jv) (include <opspace/algorithms/linalg.hpp>) computes a
// pseudo-inverse, or write J^T (J J^T)^-1 yourself.
#include <problems/1b/contract.hpp>

namespace opspace::hw2::p1b {

Vector6d control(Part part, const State& s, const Goal& goal) {
  Vector6d tau = Vector6d::Zero();
  switch (part) {
    case Part::kTipPd:
      // PART1: hold the tip at x_d, damp the joints
      //   Gamma = Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p) + A (-kvj dq)
      // FILL ME IN
      break;

    case Part::kTipPdWithoutJointDamping:
      // Question ii: the same without the joint damping
      //   Gamma = Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p)
      // FILL ME IN
      break;

    case Part::kPseudoInverseNullspace:
      // PART2: a joint task projected with the pseudo-inverse Jv+
      //   Gamma = Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p)
      //         + [I - Jv^T Jv+^T] (A (-kpj (q - q_d) - kvj dq) + g)
      // FILL ME IN
      break;

    case Part::kDynamicallyConsistentNullspace:
      // PART3: the same joint task projected with the dynamically consistent inverse Jbar_v
      //   Gamma = Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p)
      //         + [I - Jv^T Jbar_v^T] (A (-kpj (q - q_d) - kvj dq) + g)
      // FILL ME IN
      break;
  }
  return tau;
}

}  // namespace opspace::hw2::p1b
