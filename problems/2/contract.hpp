/// @file problems/2/contract.hpp
/// (included by its path, <problems/2/contract.hpp>; the build copies it under the same path for
/// the grader's sandboxed compiler, which sees the contracts and the library's headers only)
/// Problem 2: the KUKA iiwa tracks a position and Euler-parameter orientation trajectory with
/// decoupled PD control, feed-forward acceleration, null-space damping and gravity
/// compensation. Declared here, written by the student in exercises/p2.cpp, by the instructor
/// in solutions/p2.cpp.
///
/// Operational coordinates x = [x_p; lambda] (7): the position of the origin of link7 and its
/// Euler parameters, scalar first (lambda_0 = cos(theta/2)), as the problem set writes them.
#pragma once

#include <Eigen/Dense>  // everything a student may need: inverse(), solvers, decompositions

namespace opspace::hw2::p2 {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Vector7d = Eigen::Matrix<double, 7, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Matrix7d = Eigen::Matrix<double, 7, 7>;
using Matrix67d = Eigen::Matrix<double, 6, 7>;
using Matrix76d = Eigen::Matrix<double, 7, 6>;

/// What the controller knows at one tick, computed by the library from (q, qdot). Everything
/// is expressed in the base frame.
struct State {
  double t = 0.0;            ///< time (s)
  Vector7d q;                ///< joint positions (rad)
  Vector7d dq;               ///< joint velocities (rad/s)
  Eigen::Vector3d x_p;       ///< position of the operational point (origin of link7) (m)
  /// Euler parameters of link7, scalar first, unit, on the side of lambda_d
  /// (lambda . lambda_d >= 0: lambda and -lambda are the same orientation).
  Eigen::Vector4d lambda;
  Eigen::Vector3d v;         ///< linear velocity of the operational point (m/s): [v; w] = J0 dq
  Eigen::Vector3d w;         ///< angular velocity of link7 (rad/s)
  Matrix67d J0;              ///< basic Jacobian [Jv; Jw] of the operational point
  Matrix7d A;                ///< joint-space mass matrix
  Vector7d g;                ///< gravity torques
  Matrix6d Lambda0;          ///< task inertia (J0 A^-1 J0^T)^-1
  Matrix76d Jbar0;           ///< dynamically consistent inverse A^-1 J0^T Lambda0
  Matrix7d N0;               ///< null-space projector I - Jbar0 J0 (N0^T acts on torques)
  Vector6d p;                ///< gravity at the task, Jbar0^T g
};

/// The desired trajectory at time t and the gains (problem-set values in problems/2/run/scenario.hpp).
/// The library computes x_d and xdot_d; xddot_d is YOUR answer to 2(a), desired_acceleration(t).
struct Goal {
  Vector7d x_d;      ///< [x_d, y_d, z_d, lambda_0d, lambda_1d, lambda_2d, lambda_3d]
  Vector7d xdot_d;   ///< its time derivative
  Vector7d xddot_d;  ///< its second time derivative
  double kpx = 0;  ///< task stiffness: acceleration per unit of [x_p error (m); delta phi (rad)] (1/s^2)
  double kvx = 0;  ///< task damping: acceleration per unit of velocity error (1/s)
  double kvj = 0;  ///< joint damping of the null-space motion: acceleration per rad/s of dq (1/s)
};

/// 2(a): xddot_d(t), the second time derivative of the desired trajectory x_d(t).
Vector7d desired_acceleration(double t);

/// 2(b): [vdot_d; wdot_d] = E^+(lambda) xddot_d, E^+ evaluated at the Euler parameters `lambda`
/// (the term E_r^+ Edot_r w vanishes for Euler parameters).
Vector6d desired_twist_acceleration(const Eigen::Vector4d& lambda, const Vector7d& xddot_d);

/// 2(c): the joint torques Gamma of the operational-space tracking controller.
Vector7d control(const State& state, const Goal& goal);

}  // namespace opspace::hw2::p2
