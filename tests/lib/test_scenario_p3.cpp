// Problem 3's scenario (problems/3/run/scenario.hpp): the tool and the plane against robots.md, the goal
// against problem 2's trajectory, and the sign of the contact force the run logs.
#include <doctest/doctest.h>

#include <cmath>

#include <problems/2/run/scenario.hpp>
#include <problems/3/run/scenario.hpp>
#include "opspace/simulation/simulation.hpp"
#include "opspace/math/constants.hpp"
#include "opspace/algorithms/euler_params.hpp"
#include <Eigen/Geometry>
#include "opspace/model/urdf.hpp"
#include "grader/suite/random.hpp"

using namespace opspace;
namespace p3 = opspace::scenarios::p3;

namespace {

// robots.md: the tool face is 0.05 m ahead of link7's origin along link7's z axis.
constexpr double kFaceOffset = 0.05;

}  // namespace

TEST_CASE("problem 3 starts at rest with the tool face flat on the plane x = 0.05, touching it without penetration") {
  const Model iiwa = load_urdf(robot_path(p3::kRobotFile));
  Simulation sim(iiwa);
  sim.set_state(p3::initial_q(), p3::Vector7d::Zero());
  const Eigen::Isometry3d link7 = sim.link_pose(p3::kTipLink);
  // The desired pose at t = 0: x_d(0) = (0, 0.6, 0.6) and lambda_d(0) = (1/2)(1, 1, 1, 1),
  // the rotation by 120 deg about (1, 1, 1) that takes z to x. Newton steps reach it to
  // round-off (1e-15); 1e-12 m is a thousandth of a nanometre of penetration at most.
  const hw2::p3::Goal g = p3::goal(0.0);
  CHECK((link7.translation() - g.x_d.head<3>()).norm() < 1e-12);
  CHECK((link7.linear().col(2) - Eigen::Vector3d::UnitX()).norm() < 1e-12);
  // The face (robots.md: 0.05 m ahead of link7's origin along z) lies in the plane: with the
  // z axis along +x, every point of the disc's face has x = 0.05.
  const Eigen::Vector3d face = link7 * Eigen::Vector3d(0, 0, kFaceOffset);
  CHECK(std::abs(face.x() - p3::kPlaneX) < 1e-12);
  // Problem 2's start (the course's posture) is 5 mm and under a degree from that pose, and
  // Newton's steps with J0^+ are the smallest joint moves that close such an error: about a
  // degree. 1.5 deg flags a start that converged to another posture.
  const p3::Vector7d moved = p3::initial_q() - scenarios::p2::initial_q();
  CHECK(moved.cwiseAbs().maxCoeff() < 1.5 * kDeg);
}

TEST_CASE("problem 3's goal is problem 2's trajectory in y and z, with F_d = 10 N along x and the problem-set gains") {
  opspace::testing::Random rng(731);
  for (int k = 0; k < 10; ++k) {
    const double t = rng.uniform(0.0, 10.0);
    const hw2::p3::Goal g = p3::goal(t);
    const scenarios::p2::Reference r = scenarios::p2::desired(t);
    CHECK(g.x_d.segment<2>(1) == r.x.segment<2>(1));
    CHECK(g.xdot_d.segment<2>(1) == r.xdot.segment<2>(1));
    CHECK(g.xddot_d.segment<2>(1) == r.xddot.segment<2>(1));
    CHECK(g.F_d == (p3::Vector6d() << 10, 0, 0, 0, 0, 0).finished());
    CHECK(g.kpx == 50);
    CHECK(g.kvx == 20);
    CHECK(g.kvj == 20);
  }
}

// The probes of the force directions (issue 58): x_d = A sin(w t) along x, and lambda_d tilted
// about link7's own y axis, R(lambda_d) = R(problem 2's lambda_d) R_y(tilt). Checked against the
// closed form of the sine, the rotation matrices, and central differences (an independent
// derivative: step 1e-5 s, truncation error about h^2 |x'''| / 6, under 1e-9).
TEST_CASE("problem 3's goal moves x_d through the plane and tilts lambda_d off it, with consistent derivatives") {
  const double w = 2.0 * kPi / p3::kPeriod;
  opspace::testing::Random rng(732);
  for (int k = 0; k < 10; ++k) {
    const double t = rng.uniform(0.0, 10.0);
    const hw2::p3::Goal g = p3::goal(t);
    CHECK(g.x_d(0) == doctest::Approx(p3::kProbeAmplitude * std::sin(w * t)).epsilon(1e-12));
    const Eigen::Matrix3d tilt = Eigen::AngleAxisd(p3::kProbeTilt, Eigen::Vector3d::UnitY()).toRotationMatrix();
    const Eigen::Matrix3d expected = rotation_matrix(scenarios::p2::desired(t).x.tail<4>()) * tilt;
    CHECK((rotation_matrix(g.x_d.tail<4>()) - expected).norm() < 1e-12);
    const double h = 1e-5;
    const hw2::p3::Goal before = p3::goal(t - h), after = p3::goal(t + h);
    CHECK(((after.x_d - before.x_d) / (2 * h) - g.xdot_d).norm() < 1e-8);
    CHECK(((after.xdot_d - before.xdot_d) / (2 * h) - g.xddot_d).norm() < 1e-8);
  }
  // At t = 0 the goal is on the plane: x_d = 0, so the run starts where the face touches it.
  CHECK(p3::goal(0.0).x_d(0) == 0.0);
}

TEST_CASE("the plane pushes a penetrating tool back along -x: the tool's push on the plane is -contact_wrench") {
  const Model iiwa = load_urdf(robot_path(p3::kRobotFile));
  Simulation sim(iiwa);
  // the half-space x >= 0.05, as p3::run builds it
  const int plane = sim.add_plane(-Eigen::Vector3d::UnitX(), -p3::kPlaneX, Material{0.0, 0.0});
  // problem 2's start has the tool face 0.5 mm inside the plane (robots.md: link7's origin at
  // x = 0.0005)
  sim.set_state(scenarios::p2::initial_q(), p3::Vector7d::Zero());
  sim.step(p3::Vector7d::Zero());
  const int tool = sim.link_body(p3::kTipLink);
  REQUIRE(!sim.contacts().empty());
  for (const Contact& c : sim.contacts()) {
    CHECK(c.body == tool);  // only link7 has a collision shape
    CHECK(c.obstacle == plane);
    CHECK(c.normal.isApprox(-Eigen::Vector3d::UnitX(), 1e-9));
  }
  // the plane pushes the penetrating link7 along -x, so the tool's push on the plane, -force,
  // is along +x; frictionless: no tangential force
  const Wrench& w = sim.contact_wrench(tool);
  CHECK(w.force.x() < 0.0);
  CHECK(w.force.tail<2>().norm() < 1e-9 * std::abs(w.force.x()));
}
