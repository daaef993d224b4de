/// @file live/push.hpp
/// A push with the mouse (docs/live.md): a spring-damper pulls a picked point of a link toward
/// the mouse, scaled by the effective mass the point presents so that every link answers alike,
/// as MuJoCo's viewer perturbs a body (mjv_applyPerturbForce), and clamped to a maximum force.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "opspace/algorithms/kinematics.hpp"
#include "opspace/model/model.hpp"

namespace opspace::live {

/// The spring's law: F = m (w^2 (x_target - x_p) - 2 zeta w v_p), |F| <= max_force.
struct Spring {
  double frequency = 1.0;     ///< natural frequency f of the point on the spring (Hz): w = 2 pi f
  double damping_ratio = 1.0; ///< zeta: 1, critically damped
  double max_force = 50.0;    ///< largest |F| (N): a firm push that no arm's effort limits resist
};

/// m = 3 / trace(Jv A^-1 Jv^T): the mass the point presents to a force, averaged over the three
/// directions (Jv: its 3 x n linear Jacobian; A: the joint-space mass matrix, positive definite).
double effective_mass(const Eigen::Ref<const Eigen::MatrixXd>& Jv, const Eigen::Ref<const Eigen::MatrixXd>& A);

/// The spring's force on a point of mass `mass` at x_p moving at v_p, pulled toward x_target.
Eigen::Vector3d spring_force(const Spring& spring, double mass, const Eigen::Vector3d& x_p,
                             const Eigen::Vector3d& v_p, const Eigen::Vector3d& x_target);

/// Where the picked point is and the force that pulls it, for one step.
struct PushForce {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< the picked point, world (m)
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  ///< on it, world (N)
  double mass = 0.0;                                ///< the effective mass used (kg)
};

/// Computes a push's force at a state of a Model, with workspaces sized once: no allocation per
/// step.
class Pusher {
 public:
  /// Workspaces for `model`, which must outlive the Pusher.
  explicit Pusher(const Model& model);
  /// The force on point `local` of body `body` (its frame) at (q, qdot), pulled toward
  /// `target` (world) by `spring`.
  PushForce force(const Spring& spring, const Eigen::Ref<const Eigen::VectorXd>& q,
                  const Eigen::Ref<const Eigen::VectorXd>& qdot, int body, const Eigen::Vector3d& local,
                  const Eigen::Vector3d& target);
  /// The last force() as joint torques, Je^T F (Je: the picked point's linear Jacobian).
  const Eigen::VectorXd& joint_torque() const { return joint_torque_; }

 private:
  const Model& model_;
  Data data_;
  Matrix6Xd J0_;
  Eigen::MatrixXd Jv_;
  Eigen::LLT<Eigen::MatrixXd> llt_;  // of A, for the effective mass
  Eigen::MatrixXd Y_;                // L^-1 Jv^T
  Eigen::VectorXd joint_torque_;
};

}  // namespace opspace::live
