/// @file problems/3/contract.hpp
/// (included by its path, <problems/3/contract.hpp>; the build copies it under the same path for
/// the grader's sandboxed compiler, which sees the contracts and the library's headers only)
/// Problem 3: unified motion and force control. The KUKA iiwa pushes 10 N along +x against a
/// rigid plane at x = 0.05 with zero moment about y and z, while it tracks problem 2's y, z and
/// rotation about x. Declared here, written by the student in exercises/p3.cpp, by the
/// instructor in solutions/p3.cpp.
///
/// The task is problem 2's: the origin of link7 and its Euler parameters, x = [x_p; lambda], and
/// the twist [v; w] in the base frame. The 6 generalized-force directions [F; M] are split by
/// two constant selection matrices (the desired force is given in the base frame): Omega keeps
/// the motion-controlled directions, Omega-bar the force-controlled ones.
#pragma once

#include <Eigen/Dense>  // everything a student may need: inverse(), solvers, decompositions

#include <problems/2/contract.hpp>

namespace opspace::hw2::p3 {

using hw2::p2::Matrix6d;
using hw2::p2::Matrix67d;
using hw2::p2::Vector6d;
using hw2::p2::Vector7d;

/// What the controller knows at one tick: problem 2's State (time, q, dq, x_p, lambda on the
/// side of lambda_d, v, w, J0, A, g, Lambda0, Jbar0, N0, p), computed by the library.
using State = hw2::p2::State;

/// The goal at time t and the gains (problem-set values in problems/3/run/scenario.hpp). The library
/// computes the desired trajectory x_d, xdot_d and xddot_d: problem 2's in y, z and the rotation
/// about x. What it says in the force-controlled directions is not the law's to follow: the
/// scenario moves x_d along x through the plane and tilts lambda_d 5 degrees off it, and
/// Omega removes both. F_d is the desired generalized force.
struct Goal {
  Vector7d x_d;      ///< [x_d, y_d, z_d, lambda_0d, lambda_1d, lambda_2d, lambda_3d]
  Vector7d xdot_d;   ///< its time derivative
  Vector7d xddot_d;  ///< its second time derivative
  /// F_0d = [F_x, F_y, F_z, M_x, M_y, M_z] in the base frame, applied feed-forward in the
  /// force-controlled directions: [10, 0, 0, 0, 0, 0] (N, N m) in the scenario.
  Vector6d F_d;
  double kpx = 0;  ///< task stiffness: acceleration per unit of [x_p error (m); delta phi (rad)] (1/s^2)
  double kvx = 0;  ///< task damping: acceleration per unit of velocity error (1/s)
  double kvj = 0;  ///< joint damping of the null-space motion: acceleration per rad/s of dq (1/s)
};

/// 3(a): Omega (6x6), the selection of the motion-controlled directions of [F; M]: linear y
/// and z, rotation about x.
Matrix6d motion_selection();

/// 3(a): Omega-bar (6x6), the selection of the force-controlled directions: force along x,
/// moments about y and z. Omega + Omega-bar = I.
Matrix6d force_selection();

/// 3(b): the joint torques Gamma of the unified motion and force controller, with feed-forward
/// force control.
Vector7d control(const State& state, const Goal& goal);

}  // namespace opspace::hw2::p3
