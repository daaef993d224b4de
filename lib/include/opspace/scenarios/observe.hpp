/// @file scenarios/observe.hpp
/// What the problems' Observers (problems/<key>/run/scenario.cpp) share: the joint-space part of a
/// State, the tip of a point task, and the check of the robot's number of joints.
#pragma once

#include <stdexcept>
#include <string>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/model/model.hpp"

namespace opspace::scenarios {

/// `model`, or std::invalid_argument naming `who`, the model and `need` unless it has `dof`
/// joints. For an Observer's first member initialiser: checked before anything is looked up.
inline const Model& require_dof(const Model& model, int dof, const char* who, const char* need) {
  if (model.dof() != dof) {
    throw std::invalid_argument(std::string(who) + ": " + model.source + " has " + std::to_string(model.dof()) +
                                " joints; " + need);
  }
  return model;
}

/// s.t, s.q, s.dq, and s.A, s.g from one kinematics pass: data holds the poses of q afterwards.
template <class State>
void observe_joints(const Model& model, Data& data, double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                    const Eigen::Ref<const Eigen::VectorXd>& dq, State& s) {
  s.t = t;
  s.q = q;
  s.dq = dq;
  mass_matrix_and_gravity(model, data, q);
  s.A = data.A;
  s.g = data.g;
}

/// s.x, s.Jv and s.dx = Jv dq of point p on `frame`, from the poses in data (J0: workspace).
template <class State>
void observe_tip(const Model& model, const Data& data, int frame, const Eigen::Vector3d& p, Matrix6Xd& J0,
                 State& s) {
  s.x = point_position(model, data, frame, p);
  point_jacobian(model, data, frame, p, J0);
  s.Jv = J0.topRows<3>();
  s.dx.noalias() = s.Jv * s.dq;
}

}  // namespace opspace::scenarios
