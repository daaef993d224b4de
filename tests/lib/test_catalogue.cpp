// The robot catalogue (opspace/model/catalogue.hpp): every entry loads and its task point is on
// its named link, and each named configuration puts the robot where the problem set and
// robots.md say it starts (the scenarios read these). Each expected number is the
// course's, never one this code printed.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "opspace/algorithms/kinematics.hpp"
#include "opspace/math/constants.hpp"
#include "opspace/model/catalogue.hpp"

using namespace opspace;
namespace cat = opspace::catalogue;

namespace {

/// The task point's position at q, as a controller of the entry sees it.
Eigen::Vector3d tip_at(const Model& model, const cat::CourseRobot& robot, const Eigen::VectorXd& q) {
  Data data(model);
  forward_kinematics(model, data, q);
  return point_position(model, data, model.frame_id(robot.tip_link), cat::tip_point(robot));
}

/// Jv of the task point at q.
Eigen::Matrix3Xd tip_jacobian(const Model& model, const cat::CourseRobot& robot, const Eigen::VectorXd& q) {
  Data data(model);
  forward_kinematics(model, data, q);
  Matrix6Xd J0(6, model.dof());
  point_jacobian(model, data, model.frame_id(robot.tip_link), cat::tip_point(robot), J0);
  return J0.topRows<3>();
}

}  // namespace

TEST_CASE("every course robot loads, with its task point on a link of its model") {
  // frame_id throws std::out_of_range for a link the URDF does not have.
  std::set<std::string> keys;
  for (const cat::CourseRobot& robot : cat::kCourseRobots) {
    CAPTURE(robot.key);
    const Model model = cat::load(robot);
    CHECK(model.dof() > 0);
    CHECK_NOTHROW(model.frame_id(robot.tip_link));
    CHECK(&cat::find(robot.key) == &robot);  // found by its key, and keys are unique
    keys.insert(robot.key);
  }
  CHECK(keys.size() == cat::kCourseRobots.size());
}

TEST_CASE("an unknown robot key is refused with the keys there are") {
  try {
    cat::find("puma560");
    FAIL("find should throw");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()) == "no course robot 'puma560': pp, puma, iiwa, rrr");
  }
}

TEST_CASE("the PP robot's task point moves as x_ee = d1 + d2") {
  // Problem 1a: x_ee = d1 + d2, so Jv = [1 1] along X0 and zero along Y0 and Z0, at any q.
  const Model pp = cat::load(cat::kPP);
  for (const Eigen::Vector2d& q : {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.3, -0.2)}) {
    const Eigen::Matrix3Xd Jv = tip_jacobian(pp, cat::kPP, q);
    CAPTURE(Jv);
    CHECK((Jv - (Eigen::Matrix<double, 3, 2>() << 1, 1, 0, 0, 0, 0).finished()).norm() < 1e-12);
  }
}

TEST_CASE("the PUMA's start puts its tip where the course puts it, by x_d") {
  // robots.md: the tip (-0.2, 0, 0) of `end-effector` at q = (90, -22.5, 180, 90, 100, 180) deg
  // is at about (-0.1501, 0.8111, 0.5780) (four decimals: within 1 mm), which the problem set
  // rounds to x_d = (-0.15, 0.81, 0.58) (two decimals: within 5 mm per coordinate).
  const Model puma = cat::load(cat::kPuma);
  const Eigen::Vector3d tip = tip_at(puma, cat::kPuma, cat::puma_start_q());
  CAPTURE(tip.transpose());
  CHECK((tip - Eigen::Vector3d(-0.1501, 0.8111, 0.5780)).norm() < 1e-3);
  CHECK((tip - Eigen::Vector3d(-0.15, 0.81, 0.58)).cwiseAbs().maxCoeff() < 5e-3);
}

TEST_CASE("the iiwa's start puts link7's origin on problem 2's trajectory at t = 0") {
  // robots.md: link7's origin at q = (125.9, 39.2, -49.2, 70.0, -62.4, 80.2, -172.8) deg is at
  // about (0.0005, 0.595, 0.601) with quaternion (w, x, y, z) about (0.5, 0.5, 0.5, 0.5). The
  // angles are given to 0.05 deg (~0.7 mm at 0.8 m reach) and the position to 1 mm: allow 2 mm,
  // and 0.01 rad on the orientation. The quaternion is lambda_d(0) of problem 2: a = pi/4 makes
  // (1/sqrt2)(sin a, cos a, sin a, cos a) = (0.5, 0.5, 0.5, 0.5).
  const Model iiwa = cat::load(cat::kIiwa);
  const Eigen::Matrix<double, 7, 1> q = cat::iiwa_start_q();
  CHECK((tip_at(iiwa, cat::kIiwa, q) - Eigen::Vector3d(0.0005, 0.595, 0.601)).norm() < 2e-3);
  Data data(iiwa);
  forward_kinematics(iiwa, data, q);
  const Eigen::Quaterniond quat(frame_pose(iiwa, data, iiwa.frame_id(cat::kIiwa.tip_link)).linear());
  CAPTURE(quat.coeffs().transpose());
  CHECK(std::abs(quat.dot(Eigen::Quaterniond(0.5, 0.5, 0.5, 0.5))) > std::cos(0.01));
}

TEST_CASE("the iiwa's start is the course's angle for the last joint, within its limits") {
  // The course writes 187.2 deg for joint 7, beyond its +-175 deg limit (robots.md): the
  // catalogue's -172.8 deg is the same angle, one turn lower, and every joint is within limits.
  const Model iiwa = cat::load(cat::kIiwa);
  const Eigen::Matrix<double, 7, 1> q = cat::iiwa_start_q();
  CHECK(std::abs(q[6] + 2.0 * kPi - 187.2 * kDeg) < 1e-12);
  for (int i = 0; i < iiwa.dof(); ++i) {
    CAPTURE(i);
    CHECK(q[i] >= iiwa.bodies[i].lower);
    CHECK(q[i] <= iiwa.bodies[i].upper);
  }
}

TEST_CASE("the 3R arm's singular configuration stands it straight up, moving along X0 only") {
  // Problem 4: at theta = (0, 90 deg, 0) the arm points straight up, fully stretched: the tip
  // is above the base (x = y = 0), and elbow lock (Z0) and overhead lock (Y0) leave X0 as the
  // only direction the tip can move in, so Jv's Y0 and Z0 rows vanish and its X0 row does not.
  const Model rrr = cat::load(cat::kRRR);
  const Eigen::Vector3d q = cat::rrr_singular_q();
  CHECK(tip_at(rrr, cat::kRRR, q).head<2>().norm() < 1e-12);
  const Eigen::Matrix3Xd Jv = tip_jacobian(rrr, cat::kRRR, q);
  CAPTURE(Jv);
  CHECK(Jv.bottomRows<2>().norm() < 1e-12);
  CHECK(Jv.row(0).norm() > 0.1);  // a lever arm of link lengths (0.5 m each), not rounding
}
