// Problem 2's scenario (problems/2/run/scenario.hpp): the desired trajectory against the problem set's
// formulas and finite differences, the start pose against robots.md, the Observer against
// its definitions, and the Observers' refusal of a robot with another number of joints.
#include <doctest/doctest.h>

#include <cmath>

#include "opspace/algorithms/euler_params.hpp"
#include "opspace/math/constants.hpp"
#include <problems/1b/run/scenario.hpp>
#include <problems/2/run/scenario.hpp>
#include <problems/4/run/scenario.hpp>
#include "opspace/model/urdf.hpp"
#include <problems/2/problem_set.hpp>
#include "grader/suite/random.hpp"

using namespace opspace;
using opspace::testing::problem_set_x_d;
using opspace::testing::problem_set_xddot_d;
using opspace::testing::Random;
namespace p2 = opspace::scenarios::p2;

namespace {

}  // namespace

TEST_CASE("the desired trajectory is the problem set's x_d(t) with a unit lambda_d") {
  Random rng(701);
  for (int k = 0; k < 20; ++k) {
    const double t = rng.uniform(0.0, 10.0);
    const p2::Reference r = p2::desired(t);
    // the same formulas with w t computed in another order: round-off ~1e-15 at t <= 10
    CHECK((r.x - problem_set_x_d(t)).norm() < 1e-14);
    CHECK(std::abs(r.x.tail<4>().norm() - 1.0) < 1e-15);
    // |lambda_d| = 1 at all times, so lambda_d . lambdadot_d = 0
    CHECK(std::abs(r.x.tail<4>().dot(r.xdot.tail<4>())) < 1e-15);
  }
}

TEST_CASE("the desired acceleration equals the closed forms of problem 2(a)") {
  Random rng(702);
  for (int k = 0; k < 20; ++k) {
    const double t = rng.uniform(0.0, 10.0);
    CHECK((p2::desired(t).xddot - problem_set_xddot_d(t)).norm() < 1e-14);
  }
}

TEST_CASE("the desired velocity and acceleration are the finite differences of x_d(t)") {
  // Every derivative of x_d is bounded by a few units (a' <= pi^2/10, w = 2 pi/5 < 1.3), so
  // central differences err by ~h^2 (truncation) plus 1e-16 / h (first) or / h^2 (second
  // difference) of round-off: h = 1e-4 for first differences (error ~1e-8, bound 1e-7),
  // h = 1e-3 for the second difference (error ~1e-6 from h^2 |x""| / 12, bound 1e-5).
  Random rng(703);
  const double h = 1e-4, h2 = 1e-3;
  for (int k = 0; k < 20; ++k) {
    const double t = rng.uniform(0.0, 10.0);
    const p2::Reference r = p2::desired(t);
    CHECK(((p2::desired(t + h).x - p2::desired(t - h).x) / (2 * h) - r.xdot).norm() < 1e-7);
    CHECK(((p2::desired(t + h).xdot - p2::desired(t - h).xdot) / (2 * h) - r.xddot).norm() < 1e-7);
    CHECK(((p2::desired(t + h2).x - 2 * r.x + p2::desired(t - h2).x) / (h2 * h2) - r.xddot).norm() < 1e-5);
  }
}

TEST_CASE("E_r^+ lambdaddot_d is the derivative of w_d = E_r^+ lambdadot_d along the trajectory") {
  // Problem 2(b)'s claim E_r^+ Edot_r w = 0, checked on the actual trajectory: differentiate
  // w_d(t) = E_r^+(lambda_d) lambdadot_d numerically (h = 1e-4: error ~1e-8).
  Random rng(704);
  const double h = 1e-4;
  auto w_d = [](double t) {
    const p2::Reference r = p2::desired(t);
    return Eigen::Vector3d(euler_rate_matrix_pinv(r.x.tail<4>()) * r.xdot.tail<4>());
  };
  for (int k = 0; k < 20; ++k) {
    const double t = rng.uniform(0.0, 10.0);
    const p2::Reference r = p2::desired(t);
    const Eigen::Vector3d wdot = (w_d(t + h) - w_d(t - h)) / (2 * h);
    CHECK((euler_rate_matrix_pinv(r.x.tail<4>()) * r.xddot.tail<4>() - wdot).norm() < 1e-7);
  }
}

TEST_CASE("the desired orientation turns about one fixed axis through 2a = (pi/2) cos(2 pi t / 5)") {
  // lambda_d = cos(a) p + sin(a) r with p, r orthogonal unit quaternions: a rotation by 2a about
  // a fixed axis. Between lambda_d(0) and lambda_d(2.5 s) (a = pi/4 and -pi/4) the angle is
  // 2 (pi/4 - (-pi/4)) = pi: link7 turns half a turn and back every period.
  CHECK(rotation_angle_between(p2::desired(0.0).x.tail<4>(), p2::desired(2.5).x.tail<4>()) ==
        doctest::Approx(kPi).epsilon(1e-12));
  // and |w_d| = 2 |a'| with a' = -(pi/4)(2 pi/5) sin(2 pi t/5): at t = 1.25 s, |w_d| = pi^2/5
  const p2::Reference r = p2::desired(1.25);
  CHECK((euler_rate_matrix_pinv(r.x.tail<4>()) * r.xdot.tail<4>()).norm() ==
        doctest::Approx(kPi * kPi / 5).epsilon(1e-12));
}

TEST_CASE("the iiwa starts about 5 mm and within a degree of the desired pose, at rest") {
  // robots.md: link7's origin starts at about (0.0005, 0.595, 0.601), 5.1 mm from
  // x_d(0) = (0, 0.6, 0.6), with Euler parameters about (0.5, 0.5, 0.5, 0.5) = lambda_d(0).
  const Model iiwa = load_urdf(robot_path(p2::kRobotFile));
  p2::Observer observer(iiwa);
  const p2::Reference r = p2::desired(0.0);
  const hw2::p2::State& s = observer.observe(0.0, p2::initial_q(), Vector7d::Zero(), r.x.tail<4>());
  CHECK((s.x_p - Eigen::Vector3d(0.0005, 0.595, 0.601)).norm() < 1e-3);  // robots.md's 3 digits
  CHECK((s.x_p - r.x.head<3>()).norm() < 6e-3);
  CHECK(rotation_angle_between(s.lambda, r.x.tail<4>()) < kDeg);
  CHECK(s.v.norm() == 0.0);
  CHECK(s.w.norm() == 0.0);
}

TEST_CASE("the observer's lambda changes at the rate E_r(lambda) w of its angular velocity") {
  // Moving q along dq for +-h: lambda(q + h dq) - lambda(q - h dq) = 2 h E_r w + O(h^3): this
  // ties the rotation-matrix conversion to the angular rows of J0 (h = 1e-6, error ~1e-10).
  const Model iiwa = load_urdf(robot_path(p2::kRobotFile));
  p2::Observer observer(iiwa);
  Random rng(705);
  const double h = 1e-6;
  for (int k = 0; k < 5; ++k) {
    const Vector7d q = p2::initial_q() + rng.vector(7, -0.5, 0.5);
    const Vector7d dq = rng.vector(7);
    const Eigen::Vector4d side = p2::desired(0.0).x.tail<4>();
    const hw2::p2::State s = observer.observe(0.0, q, dq, side);
    const Eigen::Vector4d plus = observer.observe(0.0, q + h * dq, dq, s.lambda).lambda;
    const Eigen::Vector4d minus = observer.observe(0.0, q - h * dq, dq, s.lambda).lambda;
    CHECK(((plus - minus) / (2 * h) - euler_rate_matrix(s.lambda) * s.w).norm() < 1e-8);
    CHECK(s.lambda.dot(side) >= 0.0);
    CHECK(std::abs(s.lambda.norm() - 1.0) < 1e-15);
    // the operational-space matrices: N0 = I - Jbar0 J0, p = Jbar0^T g, J0 Jbar0 = I
    CHECK((s.N0 - (hw2::p2::Matrix7d::Identity() - s.Jbar0 * s.J0)).norm() < 1e-12);
    CHECK((s.p - s.Jbar0.transpose() * s.g).norm() < 1e-9 * s.g.norm());
    CHECK((s.J0 * s.Jbar0 - Eigen::Matrix<double, 6, 6>::Identity()).norm() < 1e-9);
  }
}

TEST_CASE("each problem's Observer refuses a robot with another number of joints, naming it") {
  // The observers size their fixed-size States for one robot; a wrong URDF must be named, not
  // read out of bounds.
  const Model rrr = load_urdf(robot_path("rrr.urdf"));
  const Model iiwa = load_urdf(robot_path("iiwa7.urdf"));
  CHECK_THROWS_WITH_AS(p2::Observer{rrr}, doctest::Contains("rrr.urdf has 3 joints; problem 2 needs the 7-joint iiwa"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(scenarios::p1b::Observer{iiwa},
                       doctest::Contains("iiwa7.urdf has 7 joints; problem 1b needs the 6-joint PUMA"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(scenarios::p4::Observer{iiwa}, doctest::Contains("has 7 joints; problem 4 needs the 3R elbow arm"),
                       std::invalid_argument);
}
