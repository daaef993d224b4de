// Euler parameters (euler_params.hpp) against the identities they must satisfy, closed-form
// rotations, and finite differences of rotating frames.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "opspace/algorithms/euler_params.hpp"
#include "opspace/algorithms/linalg.hpp"
#include "opspace/math/constants.hpp"
#include "grader/suite/random.hpp"

using namespace opspace;
using opspace::testing::Random;

namespace {

// Products of a few unit-size 4x3 matrices: round-off ~1e-16; 1e-12 leaves a wide margin.
constexpr double kTol = 1e-12;

Eigen::Vector4d random_unit_lambda(Random& rng) { return Eigen::Vector4d(rng.vector(4)).normalized(); }

Eigen::Vector3d random_axis(Random& rng) { return Eigen::Vector3d(rng.vector(3)).normalized(); }

Eigen::Matrix3d rot(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis).toRotationMatrix();
}

}  // namespace

TEST_CASE("E_r has orthogonal columns: E_r^T E_r = I/4 and E_r^T lambda = 0 for a unit lambda") {
  Random rng(601);
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector4d lambda = random_unit_lambda(rng);
    const Matrix43d Er = euler_rate_matrix(lambda);
    CHECK((Er.transpose() * Er - 0.25 * Eigen::Matrix3d::Identity()).norm() < kTol);
    // E_r^T lambda = 0: lambda_dot = E_r w is orthogonal to lambda, so |lambda| stays 1
    CHECK((Er.transpose() * lambda).norm() < kTol);
  }
}

TEST_CASE("E_r^+ is 4 E_r^T for a unit lambda and the Moore-Penrose inverse for any lambda") {
  Random rng(602);
  for (int k = 0; k < 10; ++k) {
    const Eigen::Vector4d unit = random_unit_lambda(rng);
    CHECK((euler_rate_matrix_pinv(unit) - 4.0 * euler_rate_matrix(unit).transpose()).norm() < kTol);
    // a non-unit lambda: compare with the SVD pseudo-inverse of linalg.hpp (an independent method)
    const Eigen::Vector4d lambda = rng.uniform(0.5, 2.0) * unit;
    const Eigen::MatrixXd svd = pseudo_inverse(euler_rate_matrix(lambda));
    CHECK((euler_rate_matrix_pinv(lambda) - svd).norm() < 1e-10);
  }
  CHECK_THROWS_AS(euler_rate_matrix_pinv(Eigen::Vector4d::Zero()), std::invalid_argument);
}

TEST_CASE("E = diag(I3, E_r) and E^+ E = I6") {
  Random rng(603);
  const Eigen::Vector4d lambda = random_unit_lambda(rng);
  const Matrix76d E = representation_matrix(lambda);
  CHECK((E.topLeftCorner<3, 3>() - Eigen::Matrix3d::Identity()).norm() == 0.0);
  CHECK(E.topRightCorner<3, 3>().norm() == 0.0);
  CHECK(E.bottomLeftCorner<4, 3>().norm() == 0.0);
  CHECK((E.bottomRightCorner<4, 3>() - euler_rate_matrix(lambda)).norm() == 0.0);
  CHECK((representation_matrix_pinv(lambda) * E - Eigen::Matrix<double, 6, 6>::Identity()).norm() < kTol);
}

TEST_CASE("lambda_dot = E_r(lambda) w for a frame spinning at a constant base-frame angular velocity") {
  // R(t) = Rot(w/|w|, |w| t) R0 spins at w in the base frame (Rdot = [w]x R). Central
  // differences with h = 1e-5 are exact to h^2 |lambda'''| / 6 ~ 1e-10 (|w| <= 2 rad/s).
  Random rng(604);
  const double h = 1e-5;
  for (int k = 0; k < 10; ++k) {
    const Eigen::Vector3d w = rng.vector(3, -1.0, 1.0);
    const Eigen::Matrix3d R0 = rot(random_axis(rng), rng.uniform(-kPi, kPi));
    const double t = rng.uniform(0.0, 2.0);
    auto lambda_at = [&](double time) {
      const Eigen::Vector4d l = euler_parameters(rot(w.normalized(), w.norm() * time) * R0);
      return same_side(l, euler_parameters(rot(w.normalized(), w.norm() * t) * R0));
    };
    const Eigen::Vector4d lambda_dot = (lambda_at(t + h) - lambda_at(t - h)) / (2.0 * h);
    CHECK((lambda_dot - euler_rate_matrix(lambda_at(t)) * w).norm() < 1e-8);
  }
}

TEST_CASE("E_r^+ Edot_r w vanishes, so [vdot; wdot] = E^+ xddot as problem 2(b) claims") {
  // Edot_r = E_r(lambda_dot) with lambda_dot = E_r(lambda) w (E_r is linear in lambda):
  // E_r^+ E_r(E_r w) w = 0 for every unit lambda and every w.
  Random rng(605);
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector4d lambda = random_unit_lambda(rng);
    const Eigen::Vector3d w = rng.vector(3, -3.0, 3.0);
    const Eigen::Vector4d lambda_dot = euler_rate_matrix(lambda) * w;
    CHECK((euler_rate_matrix_pinv(lambda) * euler_rate_matrix(lambda_dot) * w).norm() < kTol);
  }
}

TEST_CASE("euler_parameters of a rotation by theta about z is (cos theta/2, 0, 0, sin theta/2)") {
  for (double theta : {0.0, 0.3, 1.5, 3.0, -2.0}) {
    CAPTURE(theta);
    const Eigen::Vector4d lambda = euler_parameters(rot(Eigen::Vector3d::UnitZ(), theta));
    // scalar first and made non-negative: cos(theta/2) >= 0 for |theta| <= pi
    CHECK((lambda - Eigen::Vector4d(std::cos(theta / 2), 0, 0, std::sin(theta / 2))).norm() < kTol);
  }
}

TEST_CASE("euler_parameters and rotation_matrix invert each other, even for angles near pi") {
  Random rng(606);
  for (int k = 0; k < 20; ++k) {
    const double theta = k < 10 ? rng.uniform(-kPi, kPi) : kPi - rng.uniform(0.0, 1e-6);  // near pi: lambda_0 ~ 0
    const Eigen::Matrix3d R = rot(random_axis(rng), theta);
    const Eigen::Vector4d lambda = euler_parameters(R);
    CHECK(std::abs(lambda.norm() - 1.0) < kTol);
    CHECK(lambda(0) >= 0.0);
    CHECK((rotation_matrix(lambda) - R).norm() < 1e-12);
  }
}

TEST_CASE("same_side keeps the orientation and puts lambda on the side of the reference") {
  Random rng(607);
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector4d lambda = random_unit_lambda(rng), reference = random_unit_lambda(rng);
    const Eigen::Vector4d chosen = same_side(lambda, reference);
    CHECK(chosen.dot(reference) >= 0.0);
    CHECK(((chosen - lambda).norm() == 0.0 || (chosen + lambda).norm() == 0.0));
    CHECK((rotation_matrix(chosen) - rotation_matrix(lambda)).norm() < kTol);  // -lambda: same rotation
  }
}

TEST_CASE("delta_phi is 2 sin(theta/2) u when R R_d^T is a rotation by theta about u") {
  // Sign convention: delta_phi points along the rotation that takes the DESIRED orientation to
  // the CURRENT one, in the base frame (R = Rot(u, theta) R_d), so -kpx delta_phi turns back.
  Random rng(608);
  for (int k = 0; k < 20; ++k) {
    const Eigen::Matrix3d Rd = rot(random_axis(rng), rng.uniform(-kPi, kPi));
    const Eigen::Vector3d u = random_axis(rng);
    const double theta = rng.uniform(0.0, 3.0);
    const Eigen::Vector4d lambda_d = euler_parameters(Rd);
    const Eigen::Vector4d lambda = same_side(euler_parameters(rot(u, theta) * Rd), lambda_d);
    CHECK((orientation_error(lambda, lambda_d) - 2.0 * std::sin(theta / 2) * u).norm() < 1e-12);
    CHECK(rotation_angle_between(lambda, lambda_d) == doctest::Approx(theta).epsilon(1e-12));
  }
}

TEST_CASE("for a small error delta_phi is the rotation vector of R R_d^T") {
  // 2 sin(theta/2) = theta - theta^3/24 + ...: at theta = 1e-3 the difference is 4e-11.
  Random rng(609);
  const Eigen::Matrix3d Rd = rot(random_axis(rng), 1.0);
  const Eigen::Vector3d u = random_axis(rng);
  const double theta = 1e-3;
  const Eigen::Vector4d lambda_d = euler_parameters(Rd);
  const Eigen::Vector4d lambda = same_side(euler_parameters(rot(u, theta) * Rd), lambda_d);
  CHECK((orientation_error(lambda, lambda_d) - theta * u).norm() < 1e-10);
}

TEST_CASE("delta_phi has the same value with E_r^+ taken at lambda_d, for unit Euler parameters") {
  // E_r(l)^T l = 0 gives E_r^+(l)(l - l_d) = -4 E_r(l)^T l_d = 2 vec(l conj(l_d)), and
  // E_r^+(l_d)(l - l_d) = 4 E_r(l_d)^T l = -2 vec(l_d conj(l)) = 2 vec(l conj(l_d)): equal.
  // (Where the current lambda matters in problem 2 is E^+ xdot_d and E^+ xddot_d.)
  Random rng(610);
  for (int k = 0; k < 10; ++k) {
    const Eigen::Vector4d lambda = random_unit_lambda(rng), lambda_d = random_unit_lambda(rng);
    const Eigen::Vector3d at_lambda_d = euler_rate_matrix_pinv(lambda_d) * (lambda - lambda_d);
    CHECK((orientation_error(lambda, lambda_d) - at_lambda_d).norm() < kTol);
  }
}
