// Properties of Lambda and N that hold for every robot, checked on random trees of revolute
// and prismatic joints (random axes, placements, masses, inertias and armatures) at random
// states and random task points:
//   J A^-1 N^T = 0       a null-space torque N^T tau0 causes no task acceleration
//   Lambda J A^-1 J^T = I  Lambda is the inverse of the task's inverse inertia
// wherever J has full row rank. A projector built with a damped inverse (a common mistake, and
// a known-wrong variant kept here) must fail the first property: the test would otherwise not
// be able to tell a right projector from a wrong one.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/algorithms/opspace.hpp"
#include "opspace/math/constants.hpp"
#include "opspace/model/model.hpp"
#include "grader/suite/random.hpp"

using namespace opspace;
using opspace::testing::Random;

namespace {

/// A random tree of n bodies: each body's parent is the previous body (four in five) or any earlier
/// body or the base (a branch); one in four
/// joints prismatic; unit axis and placement (within 0.5 m) random; mass in [0.5, 5] kg at a
/// random centre; inertia R diag(d) R^T with d in [0.05, 0.1], so that d_i <= d_j + d_k as a
/// real body's principal moments are; armature 0 or in [0, 0.5].
Model random_robot(Random& rng, int n) {
  Model model;
  model.name = "random";
  for (int i = 0; i < n; ++i) {
    Body b;
    b.joint_name = "j" + std::to_string(i);
    b.link_name = "l" + std::to_string(i);
    b.type = rng.uniform(0, 1) < 0.25 ? JointType::kPrismatic : JointType::kRevolute;
    b.parent = i == 0 ? -1 : rng.uniform(0, 1) < 0.8 ? i - 1 : static_cast<int>(std::floor(rng.uniform(-1, i)));
    b.joint_placement.linear() = Eigen::Quaterniond(Eigen::Vector4d(rng.vector(4))).normalized().toRotationMatrix();
    b.joint_placement.translation() = 0.5 * rng.vector(3);
    b.axis = rng.vector(3).normalized();
    b.inertia.mass = rng.uniform(0.5, 5);
    b.inertia.com = 0.3 * rng.vector(3);
    const Eigen::Vector3d d(rng.uniform(0.05, 0.1), rng.uniform(0.05, 0.1), rng.uniform(0.05, 0.1));
    const Eigen::Matrix3d R = Eigen::Quaterniond(Eigen::Vector4d(rng.vector(4))).normalized().toRotationMatrix();
    b.inertia.inertia = R * d.asDiagonal() * R.transpose();
    b.armature = rng.uniform(0, 1) < 0.5 ? 0.0 : rng.uniform(0, 0.5);
    model.bodies.push_back(b);
    model.frames.push_back(Frame{b.link_name, i, Eigen::Isometry3d::Identity()});
  }
  return model;
}

/// Whether N decouples the task: |J A^-1 N^T| <= tol |J A^-1|.
bool null_space_decoupled(const Eigen::MatrixXd& A, const Eigen::MatrixXd& J, const Eigen::MatrixXd& N, double tol) {
  const Eigen::MatrixXd JAinv = J * A.inverse();
  return (JAinv * N.transpose()).norm() <= tol * JAinv.norm();
}

/// The known-wrong projector: Jbar from a damped inverse of J A^-1 J^T, (J A^-1 J^T + l^2 I)^-1.
/// Damping keeps Lambda bounded near a singularity, but its N no longer annihilates the task.
Eigen::MatrixXd damped_projector(const Eigen::MatrixXd& A, const Eigen::MatrixXd& J, double damping) {
  const Eigen::MatrixXd Ainv_Jt = A.llt().solve(J.transpose());
  const Eigen::MatrixXd Lambda_damped =
      (J * Ainv_Jt + damping * damping * Eigen::MatrixXd::Identity(J.rows(), J.rows())).inverse();
  return Eigen::MatrixXd::Identity(A.rows(), A.rows()) - Ainv_Jt * Lambda_damped * J;
}

}  // namespace

TEST_CASE("on random robots N^T decouples the task and Lambda inverts J A^-1 J^T; a damped projector does not") {
  // 60 robots of 2-10 joints, tasks of 1 to min(6, depth) rows of J0 at a random point of the
  // deepest body. J A^-1 J^T's condition number stays below 1e6 for the samples kept (those
  // with sigma_min(J) >= 1e-2 sigma_max), so both identities hold to 1e-8 of the scale (double
  // rounding times the condition number, with a margin). The damping 1e-2 is what a
  // damped-least-squares projector uses; its error is ~l^2 / mu_min >> 1e-8.
  Random rng(391);
  constexpr double kTol = 1e-8;
  constexpr double kDamping = 1e-2;
  int tested = 0;
  for (int sample = 0; sample < 60; ++sample) {
    const int n = 2 + sample % 9;
    const Model model = random_robot(rng, n);
    Data data(model);
    Eigen::VectorXd q(n);
    for (int i = 0; i < n; ++i) q(i) = model.bodies[i].type == JointType::kRevolute ? rng.uniform(-kPi, kPi) : rng.uniform(-0.5, 0.5);
    const Eigen::MatrixXd A = crba(model, data, q);
    const Eigen::VectorXd g = generalized_gravity(model, data, q);
    forward_kinematics(model, data, q);
    Matrix6Xd J0(6, n);
    // The task point is on the body farthest from the base: `depth` joints move it.
    int tip = 0, depth = 0;
    for (int i = 0; i < n; ++i) {
      int d = 0;
      for (int j = i; j >= 0; j = model.bodies[j].parent) ++d;
      if (d > depth) tip = i, depth = d;
    }
    point_jacobian(model, data, tip, 0.3 * rng.vector(3), J0);
    const int m = 1 + sample % std::min(6, depth);
    const Eigen::MatrixXd J = J0.topRows(m);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J);
    const Eigen::VectorXd sigma = svd.singularValues();
    if (sigma(m - 1) < 1e-2 * sigma(0)) continue;  // not of full row rank (a chain too short to reach)
    ++tested;
    CAPTURE(sample);
    CAPTURE(n);
    CAPTURE(m);
    TaskSpace ts(m, n);
    operational_space(A, J, g, ts);
    CHECK(ts.rank == m);
    CHECK(null_space_decoupled(A, J, ts.N, kTol));
    const Eigen::MatrixXd product = ts.Lambda * J * A.inverse() * J.transpose();
    CHECK((product - Eigen::MatrixXd::Identity(m, m)).norm() <= kTol * std::sqrt(m));
    CHECK_FALSE(null_space_decoupled(A, J, damped_projector(A, J, kDamping), kTol));
  }
  // Most samples have full row rank; the property must not pass by skipping them all.
  CHECK(tested >= 40);
  MESSAGE(tested << " of 60 random robots had a full-row-rank task");
}
