// Problem 2: the KUKA iiwa tracks a position and Euler-parameter orientation trajectory.
// Run:    bash scripts/run hw2-p2
// Grade:  bash scripts/grade --problem 2
//
// Operational coordinates x = [x_p; lambda]: position of link7's origin and its Euler
// parameters, scalar first. `s` holds what the robot knows now: s.q, s.dq, s.x_p, s.lambda
// (unit, already on the side of lambda_d), s.v, s.w, the Jacobian s.J0 = [Jv; Jw], the mass
// matrix s.A, gravity s.g, and the task quantities s.Lambda0, s.Jbar0, s.N0, s.p.
// `goal` holds x_d, xdot_d, xddot_d (the last one is your desired_acceleration(t)) and the
// gains kpx, kvx, kvj.
//
//   E_r(lambda) = 1/2 [[-l1, -l2, -l3], [l0, l3, -l2], [-l3, l0, l1], [l2, -l1, l0]]
//   E = diag(I3, E_r),  E^+ = diag(I3, E_r^+),  E_r^+ = (E_r^T E_r)^-1 E_r^T
// opspace::representation_matrix_pinv(lambda) (include <opspace/algorithms/euler_params.hpp>)
// computes E^+, or write it yourself.
#include <problems/2/contract.hpp>

namespace opspace::hw2::p2 {

// 2(a): the second time derivative of
//   x_d = 0,  y_d = 0.5 + 0.1 cos(2 pi t / 5),  z_d = 0.65 - 0.05 cos(4 pi t / 5),
//   lambda_d = (1/sqrt2) (sin a, cos a, sin a, cos a),  a = (pi/4) cos(2 pi t / 5)
// returned as [xdd_d, ydd_d, zdd_d, lambdadd_0d, lambdadd_1d, lambdadd_2d, lambdadd_3d].
Vector7d desired_acceleration(double t) {
  Vector7d xddot_d = Vector7d::Zero();
  // FILL ME IN
  return xddot_d;
}

// 2(b): the desired linear and angular accelerations
//   [vdot_d; wdot_d] = E^+(lambda) xddot_d      (E_r^+ Edot_r w = 0 for Euler parameters)
Vector6d desired_twist_acceleration(const Eigen::Vector4d& lambda, const Vector7d& xddot_d) {
  Vector6d twist_acceleration = Vector6d::Zero();
  // FILL ME IN
  return twist_acceleration;
}

// 2(c): decoupled PD with feed-forward acceleration, null-space damping, gravity compensation
//   Gamma = J0^T (Lambda0 (-kpx [x_p - x_pd; delta_phi] - kvx ([v; w] - E^+ xdot_d)
//                          + [vdot_d; wdot_d]) + p)
//         + N0^T (A (-kvj dq) + g)
//   delta_phi = E^+ (x_r - x_rd) = E_r^+ (lambda - lambda_d)
// E^+ evaluated at the CURRENT lambda (s.lambda), not at lambda_d.
Vector7d control(const State& s, const Goal& goal) {
  Vector7d tau = Vector7d::Zero();
  // FILL ME IN
  return tau;
}

}  // namespace opspace::hw2::p2
