// What the explorer page draws (web/explorer/explore.hpp), checked natively against the problem
// set's closed forms and against identities computed another way. The page's WebAssembly
// numbers are compared with these native ones in tests/vis (web/test/check_explorer.mjs).
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "explore.hpp"
#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/math/constants.hpp"
#include "page_data.hpp"
#include "robots.hpp"

namespace ex = opspace::explore;

namespace {

using opspace::kPi;

Eigen::Vector3d tip_at(const ex::Robot& r, const Eigen::VectorXd& q) {
  opspace::Data data(r.model);
  opspace::forward_kinematics(r.model, data, q);
  return opspace::point_position(r.model, data, r.tip.frame, r.tip.point);
}

}  // namespace

TEST_CASE("a tip motion along X0 moves both joints of the PP robot through J+ and only the light link through Jbar (1a-vi)") {
  const ex::Robot pp = ex::course_robot("pp");
  opspace::Data data(pp.model);
  const Eigen::Vector2d q0(0.2, -0.1);
  // Problem set 1a-iv and 1a-vi: J+ = [1/2 1/2]^T, Jbar = [0 1]^T, so dq = (s/2, s/2) and (0, s).
  const Eigen::VectorXd by_pinv = ex::tip_motion(pp.model, data, pp.tip, q0, Eigen::Vector3d::UnitX(), 0.1,
                                                 ex::Inverse::kPseudoInverse);
  const Eigen::VectorXd by_jbar = ex::tip_motion(pp.model, data, pp.tip, q0, Eigen::Vector3d::UnitX(), 0.1,
                                                 ex::Inverse::kDynamicallyConsistent);
  CHECK_MESSAGE((by_pinv - q0 - Eigen::Vector2d(0.05, 0.05)).norm() < 1e-12, "J+ moves d1 and d2 by ", (by_pinv - q0).transpose());
  CHECK_MESSAGE((by_jbar - q0 - Eigen::Vector2d(0.0, 0.1)).norm() < 1e-12,
                "Jbar should move only d2, the 5 kg link; it moved ", (by_jbar - q0).transpose());
}

TEST_CASE("a self-motion holds the tip still and moves the arm, differently through J+ and Jbar") {
  for (const char* key : {"puma", "iiwa"}) {
    INFO(key);
    const ex::Robot r = ex::course_robot(key);
    opspace::Data data(r.model);
    const Eigen::Vector3d x0 = tip_at(r, r.q0);
    Eigen::VectorXd moved[2];
    int k = 0;
    for (ex::Inverse inverse : {ex::Inverse::kPseudoInverse, ex::Inverse::kDynamicallyConsistent}) {
      moved[k] = ex::self_motion(r.model, data, r.tip, r.q0, r.self_joint, 0.5, inverse);
      // Each step's drift is second order in the step (0.01) and the Newton correction squares
      // it: 1e-8 m over 50 steps is ample, and far below the arms' millimetres.
      CHECK_MESSAGE((tip_at(r, moved[k]) - x0).norm() < 1e-8, "the tip moved by ", (tip_at(r, moved[k]) - x0).norm(), " m");
      CHECK_MESSAGE((moved[k] - r.q0).norm() > 0.1, "the arm should move along its null space");
      ++k;
    }
    // The two projectors pass different null-space vectors for the same request.
    CHECK((moved[0] - moved[1]).norm() > 1e-2);
  }
}

TEST_CASE("the ellipsoids at the tip: sigma_i of Jv, and the square root of the effective mass along every direction") {
  const ex::Robot iiwa = ex::course_robot("iiwa");
  opspace::Data data(iiwa.model);
  const ex::TipView v = ex::view(iiwa.model, data, iiwa.tip, iiwa.q0);
  // Jv Jv^T = U diag(sigma^2) U^T (the SVD).
  const Eigen::Matrix3d JJt = v.Jv * v.Jv.transpose();
  const Eigen::Matrix3d from_axes = v.velocity_axes * v.velocity_radii.cwiseAbs2().asDiagonal() * v.velocity_axes.transpose();
  CHECK((JJt - from_axes).norm() < 1e-12 * JJt.norm());
  // Radius of the mass ellipsoid along u, r(u) = (sum_i (u . a_i)^2 / r_i^2)^-1/2, against
  // sqrt(m_u) with m_u = 1 / (u^T Jv A^-1 Jv^T u) through an explicit LU inverse of A.
  const Eigen::MatrixXd A = opspace::crba(iiwa.model, data, iiwa.q0);
  const Eigen::Matrix3d Lambda_inv = v.Jv * A.fullPivLu().inverse() * v.Jv.transpose();
  for (const Eigen::Vector3d& u : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1.0 / 3, 2.0 / 3, -2.0 / 3)}) {
    double s = 0.0;
    for (int i = 0; i < 3; ++i) s += std::pow(u.dot(v.mass_axes.col(i)) / v.mass_radii(i), 2);
    const double m_u = 1.0 / (u.transpose() * Lambda_inv * u);
    CHECK(1.0 / std::sqrt(s) == doctest::Approx(std::sqrt(m_u)).epsilon(1e-12));
  }
}

TEST_CASE("the 3R arm at theta = (0, 90 deg, 0): Z0 Type I, Y0 Type II, infinite effective mass along both") {
  const ex::Robot rrr = ex::course_robot("rrr");
  opspace::Data data(rrr.model);
  const ex::TipView v = ex::view(rrr.model, data, rrr.tip, Eigen::Vector3d(0.0, kPi / 2, 0.0));
  // Problem 4 ii-iv.
  REQUIRE(v.singularities.linear.rank == 1);
  REQUIRE(v.singularities.type_one == 1);
  CHECK(std::abs(v.singularities.linear.singular().col(0).z()) == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(std::abs(v.singularities.linear.singular().col(1).y()) == doctest::Approx(1.0).epsilon(1e-12));
  int infinite = 0;
  for (int i = 0; i < 3; ++i) infinite += std::isinf(v.mass_radii(i)) ? 1 : 0;
  CHECK_MESSAGE(infinite == 2, "no force along Y0 or Z0 accelerates the tip: m_u is infinite there");
}

TEST_CASE("the page's request is refused when it is not finite or not the robot's size") {
  const ex::Robot rrr = ex::course_robot("rrr");
  opspace::Data data(rrr.model);
  ex::Request r;
  r.q = Eigen::Vector3d(0.0, std::numeric_limits<double>::quiet_NaN(), 0.0);
  CHECK_THROWS_AS(ex::view_json(rrr.model, data, rrr.tip, r), std::invalid_argument);
  r.q = Eigen::Vector2d::Zero();
  CHECK_THROWS_AS(ex::view_json(rrr.model, data, rrr.tip, r), std::invalid_argument);
  r.q = Eigen::Vector3d::Zero();
  r.u.setZero();
  CHECK_THROWS_AS(ex::view_json(rrr.model, data, rrr.tip, r), std::invalid_argument);
  r.u = Eigen::Vector3d::UnitX();
  r.self_joint = 3;
  r.self_s = 0.1;
  CHECK_THROWS_AS(ex::view_json(rrr.model, data, rrr.tip, r), std::invalid_argument);
}

TEST_CASE("a joint without limits reaches the page as null, which JSON can read, not as inf") {
  ex::Robot rrr = ex::course_robot("rrr");
  const double inf = std::numeric_limits<double>::infinity();
  rrr.model.bodies[0].lower = -inf;  // a continuous joint, as urdf.cpp reads one
  rrr.model.bodies[0].upper = inf;
  const std::string json = ex::robot_json(rrr);
  const std::size_t from = json.find("\"joints\":");
  REQUIRE(from != std::string::npos);
  const std::string joints = json.substr(from, json.find("\"q0\":", from) - from);
  const std::string first = "{\"name\":\"" + rrr.model.bodies[0].joint_name + "\",\"prismatic\":false,";
  CHECK_MESSAGE(joints.find(first + "\"lower\":null,\"upper\":null}") != std::string::npos, "the joints: ", joints);
  // JSON has no infinity: one "inf" and JSON.parse rejects the whole page. (The Model's text, a
  // JSON string, does write inf: read_model_text reads it.)
  CHECK_MESSAGE(joints.find("inf") == std::string::npos, "the joints: ", joints);
  // The other joints keep their URDF limits, as numbers.
  CHECK_MESSAGE(joints.find("null", joints.find(first) + first.size() + 30) == std::string::npos, "the joints: ", joints);
}
