// A push with the mouse: the spring's force and the effective mass (live/push.hpp).
#include "opspace/live/push.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/math/constants.hpp"

namespace opspace::live {

namespace {

// 3 / trace(Jv A^-1 Jv^T) with A = L L^T factored in `llt`: the trace is the squared norm of
// Y = L^-1 Jv^T (Y: a workspace, no allocation once sized).
double mass_from(const Eigen::LLT<Eigen::MatrixXd>& llt, const Eigen::Ref<const Eigen::MatrixXd>& Jv, Eigen::MatrixXd& Y) {
  if (llt.info() != Eigen::Success) throw std::invalid_argument("effective_mass: A is not positive definite");
  Y = Jv.transpose();
  llt.matrixL().solveInPlace(Y);
  const double trace = Y.squaredNorm();
  // A point on the base (Jv = 0) cannot be moved: infinitely heavy, which the clamp bounds.
  return trace > 0.0 ? 3.0 / trace : INFINITY;
}

}  // namespace

double effective_mass(const Eigen::Ref<const Eigen::MatrixXd>& Jv, const Eigen::Ref<const Eigen::MatrixXd>& A) {
  Eigen::MatrixXd Y;
  return mass_from(Eigen::LLT<Eigen::MatrixXd>(A), Jv, Y);
}

Eigen::Vector3d spring_force(const Spring& spring, double mass, const Eigen::Vector3d& x_p,
                             const Eigen::Vector3d& v_p, const Eigen::Vector3d& x_target) {
  const double w = 2.0 * kPi * spring.frequency;
  Eigen::Vector3d F = w * w * (x_target - x_p) - 2.0 * spring.damping_ratio * w * v_p;
  if (F.isZero(0.0)) return F;
  F *= std::isfinite(mass) ? mass : 1.0;
  if (!std::isfinite(mass) || F.norm() > spring.max_force) F *= spring.max_force / F.norm();
  return F;
}

Pusher::Pusher(const Model& model)
    : model_(model), data_(model), J0_(6, model.dof()), Jv_(3, model.dof()), llt_(model.dof()), Y_(model.dof(), 3),
      joint_torque_(Eigen::VectorXd::Zero(model.dof())) {}

PushForce Pusher::force(const Spring& spring, const Eigen::Ref<const Eigen::VectorXd>& q,
                        const Eigen::Ref<const Eigen::VectorXd>& qdot, int body, const Eigen::Vector3d& local,
                        const Eigen::Vector3d& target) {
  if (body < 0 || body >= model_.dof()) {
    throw std::out_of_range("Pusher: body index " + std::to_string(body) + " is not one of the " +
                            std::to_string(model_.dof()) + " bodies of '" + model_.name + "'");
  }
  const int frame = model_.frame_id(model_.bodies[body].link_name);
  crba(model_, data_, q);  // also the poses (forward kinematics)
  point_jacobian(model_, data_, frame, local, J0_);
  Jv_ = J0_.topRows<3>();
  PushForce push;
  push.point = point_position(model_, data_, frame, local);
  push.mass = mass_from(llt_.compute(data_.A), Jv_, Y_);
  push.force = spring_force(spring, push.mass, push.point, Jv_ * qdot, target);
  joint_torque_.noalias() = Jv_.transpose() * push.force;
  return push;
}

}  // namespace opspace::live
