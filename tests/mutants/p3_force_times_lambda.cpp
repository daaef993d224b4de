// A known-wrong problem 3 (the catalogue's "the desired force multiplied by Lambda0",
// problems/3/grade/mistakes.cpp) as a student would write it: solutions/p3.cpp with
// Omega-bar F_d sent through Lambda0 like an acceleration. Graded as a submission by
// check_mutant_page.sh: the report page plots its force error far above the 1 N bound while
// the reference's stays under it (problems/3/guide.md's picture).
#include "opspace/algorithms/euler_params.hpp"
#include <problems/3/contract.hpp>

namespace opspace::hw2::p3 {

Matrix6d motion_selection() {
  Vector6d diagonal;
  diagonal << 0, 1, 1, 1, 0, 0;  // y, z, rotation about x
  return diagonal.asDiagonal();
}

Matrix6d force_selection() {
  Vector6d diagonal;
  diagonal << 1, 0, 0, 0, 1, 1;  // force along x, moments about y and z
  return diagonal.asDiagonal();
}

Vector7d control(const State& s, const Goal& goal) {
  const Matrix67d E_pinv = representation_matrix_pinv(s.lambda);  // at the CURRENT lambda
  Vector6d error, twist;
  error << s.x_p - goal.x_d.head<3>(), orientation_error(s.lambda, goal.x_d.tail<4>());
  twist << s.v, s.w;
  const Vector6d motion = -goal.kpx * error - goal.kvx * (twist - E_pinv * goal.xdot_d) + E_pinv * goal.xddot_d;
  const Vector6d F = s.Lambda0 * (motion_selection() * motion + force_selection() * goal.F_d) + s.p;  // the mistake
  return s.J0.transpose() * F + s.N0.transpose() * (s.A * (-goal.kvj * s.dq) + s.g);
}

}  // namespace opspace::hw2::p3
