// Problem 3's scenario (scenarios/p3.hpp): the tool and the plane against robots.md, the goal
// against problem 2's trajectory, and the sign of the contact force the run logs.
#include <doctest/doctest.h>

#include <cmath>

#include "opspace/scenarios.hpp"
#include "opspace/simulation.hpp"
#include "opspace/urdf.hpp"
#include "support/random.hpp"

using namespace opspace;
namespace p3 = opspace::scenarios::p3;

namespace {

// robots.md: the tool face is 0.05 m ahead of link7's origin along link7's z axis.
constexpr double kFaceOffset = 0.05;

}  // namespace

TEST_CASE("problem 3 starts with the tool face on the plane x = 0.05 and link7's z axis along +x") {
  const Model iiwa = load_urdf(robot_path(p3::kRobotFile));
  Simulation sim(iiwa);
  sim.set_state(p3::initial_q(), p3::Vector7d::Zero());
  const Eigen::Isometry3d link7 = sim.link_pose(p3::kTipLink);
  const Eigen::Vector3d face = link7 * Eigen::Vector3d(0, 0, kFaceOffset);
  // robots.md: link7's origin starts at x = 0.0005 (problem 2's x_d = 0 within 5 mm), so the
  // face is within a millimetre of the plane.
  CHECK(std::abs(face.x() - p3::kPlaneX) < 1e-3);
  // and link7's z axis points along +x to within a degree: the face is parallel to the plane
  CHECK(link7.linear().col(2).x() > std::cos(3.14159265358979323846 / 180.0));
}

TEST_CASE("problem 3's goal is problem 2's trajectory with F_d = 10 N along x and the problem-set gains") {
  opspace::testing::Random rng(731);
  for (int k = 0; k < 10; ++k) {
    const double t = rng.uniform(0.0, 10.0);
    const hw2::p3::Goal g = p3::goal(t);
    const scenarios::p2::Reference r = scenarios::p2::desired(t);
    CHECK(g.x_d == r.x);
    CHECK(g.xdot_d == r.xdot);
    CHECK(g.xddot_d == r.xddot);
    CHECK(g.F_d == (p3::Vector6d() << 10, 0, 0, 0, 0, 0).finished());
    CHECK(g.kpx == 50);
    CHECK(g.kvx == 20);
    CHECK(g.kvj == 20);
  }
}

TEST_CASE("the plane pushes a penetrating tool back along -x: the tool's push on the plane is -contact_wrench") {
  const Model iiwa = load_urdf(robot_path(p3::kRobotFile));
  Simulation sim(iiwa);
  // the half-space x >= 0.05, as p3::run builds it
  const int plane = sim.add_plane(-Eigen::Vector3d::UnitX(), -p3::kPlaneX, Material{0.0, 0.0});
  sim.set_state(p3::initial_q(), p3::Vector7d::Zero());
  sim.step(p3::Vector7d::Zero());
  const int tool = sim.link_body(p3::kTipLink);
  REQUIRE(!sim.contacts().empty());
  for (const Contact& c : sim.contacts()) {
    CHECK(c.body == tool);  // only link7 has a collision shape
    CHECK(c.obstacle == plane);
    CHECK(c.normal.isApprox(-Eigen::Vector3d::UnitX(), 1e-9));
  }
  // the face starts 0.5 mm inside: the plane pushes link7 along -x, so the tool's push on the
  // plane, -force, is along +x; frictionless: no tangential force
  const Wrench& w = sim.contact_wrench(tool);
  CHECK(w.force.x() < 0.0);
  CHECK(w.force.tail<2>().norm() < 1e-9 * std::abs(w.force.x()));
}
