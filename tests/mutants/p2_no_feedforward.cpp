// A known-wrong problem 2 (the catalogue's "no feed-forward [vdot_d; wdot_d]",
// problems/2/grade/mistakes.cpp) as a student would write it: solutions/p2.cpp with 2(b)'s
// E^+ xddot_d left out of the controller's desired acceleration. Graded as a submission by
// check_mutant_page.sh: the report page plots its position error a few mm above the 1 mm bound
// while the reference's stays under it (problems/2/guide.md's picture).
#include <problems/2/contract.hpp>

#include <cmath>

namespace opspace::hw2::p2 {

namespace {

constexpr double kPi = 3.14159265358979323846;

// E_r(lambda) of problem 2(b): lambda_dot = E_r w
Eigen::Matrix<double, 4, 3> E_r(const Eigen::Vector4d& l) {
  Eigen::Matrix<double, 4, 3> E;
  E << -l(1), -l(2), -l(3),
        l(0),  l(3), -l(2),
       -l(3),  l(0),  l(1),
        l(2), -l(1),  l(0);
  return 0.5 * E;
}

// E^+ = diag(I3, E_r^+), E_r^+ = (E_r^T E_r)^-1 E_r^T = 4 E_r^T for a unit lambda
Matrix67d E_pinv(const Eigen::Vector4d& lambda) {
  Matrix67d Ep = Matrix67d::Zero();
  Ep.topLeftCorner<3, 3>().setIdentity();
  Ep.bottomRightCorner<3, 4>() = 4.0 * E_r(lambda).transpose();
  return Ep;
}

}  // namespace

Vector7d desired_acceleration(double t) {
  const double r2 = std::sqrt(2.0);
  const double c1 = std::cos(2.0 * kPi * t / 5.0), s1 = std::sin(2.0 * kPi * t / 5.0);
  const double c2 = std::cos(4.0 * kPi * t / 5.0);
  const double a = kPi / 4.0 * c1;
  const double sa = std::sin(a), ca = std::cos(a);
  const double k4 = std::pow(kPi, 4) / (100.0 * r2), k3 = std::pow(kPi, 3) / (25.0 * r2);
  Vector7d xdd;
  xdd(0) = 0.0;
  xdd(1) = -2.0 * kPi * kPi / 125.0 * c1;
  xdd(2) = 4.0 * kPi * kPi / 125.0 * c2;
  xdd(3) = -k4 * sa * s1 * s1 - k3 * ca * c1;
  xdd(4) = -k4 * ca * s1 * s1 + k3 * sa * c1;
  xdd(5) = xdd(3);
  xdd(6) = xdd(4);
  return xdd;
}

Vector6d desired_twist_acceleration(const Eigen::Vector4d& lambda, const Vector7d& xddot_d) {
  return E_pinv(lambda) * xddot_d;
}

Vector7d control(const State& s, const Goal& goal) {
  const Matrix67d Ep = E_pinv(s.lambda);  // at the CURRENT lambda
  Vector6d error;
  error << s.x_p - goal.x_d.head<3>(),
           Ep.bottomRightCorner<3, 4>() * (s.lambda - goal.x_d.tail<4>());  // delta_phi
  Vector6d twist;
  twist << s.v, s.w;
  // The mistake: no + desired_twist_acceleration(s.lambda, goal.xddot_d) inside Lambda0 (...).
  const Vector6d F = s.Lambda0 * (-goal.kpx * error - goal.kvx * (twist - Ep * goal.xdot_d)) + s.p;
  return s.J0.transpose() * F + s.N0.transpose() * (s.A * (-goal.kvj * s.dq) + s.g);
}

}  // namespace opspace::hw2::p2
