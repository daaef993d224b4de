// Kinematics of the models in robots/: Jacobians against finite differences of the pose they
// differentiate, Jdot qdot against finite differences of J qdot, and a fixed joint's frame as a
// tip (where the course's configurations put each task point: test_catalogue.cpp).
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "opspace/algorithms/kinematics.hpp"
#include "opspace/math/constants.hpp"
#include "opspace/model/urdf.hpp"
#include "grader/suite/random.hpp"

using namespace opspace;
using opspace::testing::Random;

namespace {

const char* const kRobots[] = {"pp.urdf", "puma.urdf", "iiwa7.urdf", "rrr.urdf"};
constexpr double kStep = 1e-6;  // central differences: truncation ~ h^2, round-off ~ 1e-16 / h
constexpr double kFdTol = 1e-7;

/// Random joint vector: angles in [-pi, pi), prismatic travel in [-1, 1).
Eigen::VectorXd random_q(const Model& model, Random& rng) {
  Eigen::VectorXd q(model.dof());
  for (int i = 0; i < model.dof(); ++i) {
    q(i) = model.bodies[i].type == JointType::kRevolute ? rng.uniform(-kPi, kPi) : rng.uniform(-1, 1);
  }
  return q;
}

/// w such that R1 = exp([w] dt) R0 for small dt: the angle-axis of R1 R0^T (base frame).
Eigen::Vector3d rotation_vector(const Eigen::Matrix3d& R1, const Eigen::Matrix3d& R0) {
  const Eigen::AngleAxisd aa(R1 * R0.transpose());
  return aa.angle() * aa.axis();
}

/// Calls trial(model, data) `trials` times on each robot of kRobots; a failure names the file.
template <class Trial>
void each_model(int trials, const Trial& trial) {
  for (const char* file : kRobots) {
    const Model model = load_urdf(robot_path(file));
    Data data(model);
    CAPTURE(file);
    for (int t = 0; t < trials; ++t) trial(model, data);
  }
}

}  // namespace

TEST_CASE("Jv and Jw are the derivatives of a point's position and orientation") {
  Random rng(301);
  each_model(20, [&](const Model& model, Data& data) {
    const Eigen::VectorXd q = random_q(model, rng);
    const int frame = static_cast<int>(rng.uniform(0, static_cast<double>(model.frames.size())));
    const Eigen::Vector3d p = rng.vector(3, -0.3, 0.3);
    forward_kinematics(model, data, q);
    Matrix6Xd J(6, model.dof());
    point_jacobian(model, data, frame, p, J);
    for (int i = 0; i < model.dof(); ++i) {
      // Column i = d/dq_i of (position, orientation), by central differences.
      Eigen::VectorXd qp = q, qm = q;
      qp(i) += kStep;
      qm(i) -= kStep;
      forward_kinematics(model, data, qp);
      const Eigen::Isometry3d Xp = frame_pose(model, data, frame);
      forward_kinematics(model, data, qm);
      const Eigen::Isometry3d Xm = frame_pose(model, data, frame);
      const Eigen::Vector3d dv = (Xp * p - Xm * p) / (2 * kStep);
      const Eigen::Vector3d dw = rotation_vector(Xp.linear(), Xm.linear()) / (2 * kStep);
      CAPTURE(i);
      CHECK_MESSAGE((J.col(i).head<3>() - dv).norm() < kFdTol, "Jv column ", i, " is not dx/dq_", i);
      CHECK_MESSAGE((J.col(i).tail<3>() - dw).norm() < kFdTol, "Jw column ", i, " is not the rotation rate per unit q_", i);
    }
  });
}

TEST_CASE("point_velocity is J0 qdot") {
  Random rng(302);
  each_model(10, [&](const Model& model, Data& data) {
    const int frame = static_cast<int>(model.frames.size()) - 1;
    forward_kinematics(model, data, random_q(model, rng));
    const Eigen::VectorXd qdot = rng.vector(model.dof(), -2, 2);
    Matrix6Xd J(6, model.dof());
    const Eigen::Vector3d p(0.1, -0.05, 0.02);
    point_jacobian(model, data, frame, p, J);
    // Same sum over the chain, formed without the matrix: round-off only.
    CHECK((point_velocity(model, data, frame, p, qdot) - J * qdot).norm() < 1e-12);
  });
}

TEST_CASE("Jdot qdot is the rate of change of J qdot along the motion") {
  // d/dt (J(q) qdot) at constant qdot = [J(q + h qdot) - J(q - h qdot)] qdot / 2h.
  Random rng(303);
  each_model(20, [&](const Model& model, Data& data) {
    const Eigen::VectorXd q = random_q(model, rng);
    const Eigen::VectorXd qdot = rng.vector(model.dof(), -2, 2);
    const int frame = static_cast<int>(rng.uniform(0, static_cast<double>(model.frames.size())));
    const Eigen::Vector3d p = rng.vector(3, -0.3, 0.3);
    const Vector6d Jdot_qdot = point_jacobian_dot_times_qdot(model, data, frame, p, q, qdot);
    forward_kinematics(model, data, q + kStep * qdot);
    const Vector6d vp = point_velocity(model, data, frame, p, qdot);
    forward_kinematics(model, data, q - kStep * qdot);
    const Vector6d vm = point_velocity(model, data, frame, p, qdot);
    CHECK_MESSAGE((Jdot_qdot - (vp - vm) / (2 * kStep)).norm() < 1e-6,
                  "Jdot qdot must be the point's acceleration [a; wdot] when qdd = 0");
  });
}

TEST_CASE("a fixed joint's child keeps its frame, so a tool frame can be the tip") {
  // rrr.urdf: end-effector is fixed 0.5 m along x of link3, so at q = 0 (links along +X0)
  // the tip is at 0.05 + 0.3 above the base and 0.5 + 0.5 along X0; at (0, 90 deg, 0) the arm
  // points straight up: (0, 0, 0.05 + 0.3 + 1.0).
  const Model model = load_urdf(robot_path("rrr.urdf"));
  Data data(model);
  const int ee = model.frame_id("end-effector");
  CHECK(model.frames[ee].body == model.joint_id("joint3"));
  forward_kinematics(model, data, Eigen::Vector3d::Zero());
  CHECK((point_position(model, data, ee, Eigen::Vector3d::Zero()) - Eigen::Vector3d(1.0, 0, 0.35)).norm() < 1e-12);
  forward_kinematics(model, data, Eigen::Vector3d(0, kPi / 2, 0));
  CHECK((point_position(model, data, ee, Eigen::Vector3d::Zero()) - Eigen::Vector3d(0, 0, 1.35)).norm() < 1e-12);
}
