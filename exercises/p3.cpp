// Problem 3: unified motion and force control against the plane x = 0.05.
// Run:    bash scripts/run hw2-p3
// Grade:  bash scripts/grade --problem 3
//
// `s` is problem 2's State: s.q, s.dq, s.x_p, s.lambda (unit, on the side of lambda_d), s.v,
// s.w, the Jacobian s.J0 = [Jv; Jw], the mass matrix s.A, gravity s.g, and the task quantities
// s.Lambda0, s.Jbar0, s.N0, s.p. `goal` holds x_d, xdot_d, xddot_d (problem 2's trajectory,
// computed by the library), the desired force goal.F_d = [F_x, F_y, F_z, M_x, M_y, M_z] and the
// gains kpx, kvx, kvj.
// opspace::representation_matrix_pinv(lambda) and opspace::orientation_error(lambda, lambda_d)
// (include <opspace/algorithms/euler_params.hpp>) compute E^+ and delta_phi, or reuse your
// problem 2.
#include <problems/3/contract.hpp>

namespace opspace::hw2::p3 {

// 3(a): Omega selects the motion-controlled directions of [F; M] (base frame): the force along
// y and z and the moment about x.
Matrix6d motion_selection() {
  Matrix6d omega = Matrix6d::Zero();
  // FILL ME IN
  return omega;
}

// 3(a): Omega-bar selects the force-controlled directions: the force along x and the moments
// about y and z.
Matrix6d force_selection() {
  Matrix6d omega_bar = Matrix6d::Zero();
  // FILL ME IN
  return omega_bar;
}

// 3(b): unified motion and force control, feed-forward force
//   Gamma = J0^T (Lambda0 Omega (-kpx [x_p - x_pd; delta_phi] - kvx ([v; w] - E^+ xdot_d)
//                                + [vdot_d; wdot_d])
//                 + p + Omega-bar F_d)
//         + N0^T (A (-kvj dq) + g)
//   delta_phi = E_r^+ (lambda - lambda_d),  [vdot_d; wdot_d] = E^+ xddot_d
// E^+ evaluated at the CURRENT lambda (s.lambda), not at lambda_d.
// (problems/3/guide.md: does the law need anything more in the force directions?)
Vector7d control(const State& s, const Goal& goal) {
  Vector7d tau = Vector7d::Zero();
  // FILL ME IN
  return tau;
}

}  // namespace opspace::hw2::p3
