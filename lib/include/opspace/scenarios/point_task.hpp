/// @file scenarios/point_task.hpp
/// The Observer of a point task, written once for the problems whose State is a tip's: problem
/// 1b's PUMA and every problem scripts/new-problem makes. Its State has t, q, dq (observe_joints),
/// x, dx, Jv (observe_tip), A, g and the task's Lambda_v = (Jv A^-1 Jv^T)^-1,
/// Jbar_v = A^-1 Jv^T Lambda_v and p = Jbar_v^T g (operational_space).
#pragma once

#include <Eigen/Core>

#include "opspace/algorithms/opspace.hpp"
#include "opspace/model/model.hpp"
#include "opspace/scenarios/observe.hpp"

namespace opspace::scenarios {

/// The State of the point `point` of link `link`, computed from (t, q, dq) without allocating.
template <class State>
class PointTaskObserver {
 public:
  /// Workspaces sized for `model`, which must outlive the Observer. Throws std::invalid_argument
  /// naming `who` and `need` unless it has `dof` joints, std::out_of_range unless it has `link`.
  PointTaskObserver(const Model& model, int dof, const char* link, const Eigen::Vector3d& point, const char* who,
                    const char* need)
      : model_(require_dof(model, dof, who, need)), data_(model), task_(3, model.dof()), J0_(6, model.dof()),
        frame_(model.frame_id(link)), point_(point) {}

  /// The State at time t: x, dx, Jv, A, g, Lambda_v, Jbar_v, p at (q, dq).
  const State& observe(double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                       const Eigen::Ref<const Eigen::VectorXd>& dq) {
    State& s = state_;
    observe_joints(model_, data_, t, q, dq, s);
    observe_tip(model_, data_, frame_, point_, J0_, s);
    operational_space(s.A, s.Jv, s.g, task_);
    s.Lambda_v = task_.Lambda;
    s.Jbar_v = task_.Jbar;
    s.p = task_.p;
    return s;
  }
  const State& state() const { return state_; }  ///< the last observe()'s State

 private:
  const Model& model_;
  Data data_;
  TaskSpace task_;
  Matrix6Xd J0_;
  int frame_;
  Eigen::Vector3d point_;
  State state_;
};

}  // namespace opspace::scenarios
