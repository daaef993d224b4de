/// @file problems/1b/run/offset.hpp
/// Problem 1b: where a steady push holds the tip (docs/live.md, "What a push does to the tip").
///
/// Under PART3, with an external force F on a point of Jacobian Je, A ddq + b + g = Gamma + Je^T F.
/// Times Jv A^-1, with Jv A^-1 Jv^T = Lambda_v^-1, Jv A^-1 g = Lambda_v^-1 p and
/// Jv A^-1 (I - Jv^T Jbar_v^T) = 0 (the projector: no null-space torque accelerates the tip):
///   ddx = -kpx e - kvx de + Jv A^-1 Je^T F + (dJv dq - Jv A^-1 b),   e = x - x_d.
/// At rest (dq = 0, de = dde = 0): e = Jv A^-1 Je^T F / kpx = (kpx Lambda_v)^-1 Jbar_v^T Je^T F,
/// the tip force the push amounts to over the task's stiffness. PART1 gives the same (its joint
/// damping vanishes at rest); under PART2 the joint task's own leak adds to it.
#pragma once

#include <Eigen/Core>

#include <problems/1b/contract.hpp>

namespace opspace::live {

/// e = Jv A^-1 tau_push / kpx (m), with Jv and A of `s` and tau_push = Je^T F (N m).
Eigen::Vector3d p1b_static_tip_offset(const hw2::p1b::State& s, const Eigen::Ref<const Eigen::VectorXd>& tau_push,
                                      double kpx);

}  // namespace opspace::live
