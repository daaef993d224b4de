/// @file problems/1b/contract.hpp
/// (included by its path, <problems/1b/contract.hpp>; the build copies it under the same path for
/// the grader's sandboxed compiler, which sees the contracts and the library's headers only)
/// Problem 1b: the PUMA 560 holds its tip still while its second joint moves in the null
/// space of the tip task. Declared here, written by the student in exercises/p1b.cpp, by
/// the instructor in solutions/p1b.cpp.
#pragma once

#include <Eigen/Dense>  // everything a student may need: inverse(), solvers, decompositions

namespace opspace::hw2::p1b {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Matrix36d = Eigen::Matrix<double, 3, 6>;
using Matrix63d = Eigen::Matrix<double, 6, 3>;

/// Which control law of problem 1b to apply.
enum class Part {
  kTipPd = 1,                           ///< PART1 (question ii): tip PD + joint damping
  kPseudoInverseNullspace = 2,          ///< PART2 (question iii): null-space task, J+ projector
  kDynamicallyConsistentNullspace = 3,  ///< PART3 (question iv): null-space task, Jbar projector
  kTipPdWithoutJointDamping = 4,        ///< question ii's variant: PART1 without A(-kvj qdot)
};

/// What the controller knows at one tick, computed by the library from (q, qdot).
/// Everything is expressed in the base frame; the tip is the point (-0.2, 0, 0) of the
/// PUMA's `end-effector` link.
struct State {
  double t = 0.0;         ///< time (s)
  Vector6d q;             ///< joint positions (rad)
  Vector6d dq;            ///< joint velocities (rad/s)
  Eigen::Vector3d x;      ///< tip position (m)
  Eigen::Vector3d dx;     ///< tip velocity (m/s)
  Matrix36d Jv;           ///< tip linear-velocity Jacobian: dx = Jv dq
  Matrix6d A;             ///< joint-space mass matrix
  Vector6d g;             ///< gravity torques
  Eigen::Matrix3d Lambda_v;  ///< task inertia (Jv A^-1 Jv^T)^-1
  Matrix63d Jbar_v;          ///< dynamically consistent inverse A^-1 Jv^T Lambda_v
  Eigen::Vector3d p;         ///< gravity at the tip, Jbar_v^T g
};

/// The goal and gains (problem set values in problems/1b/run/scenario.hpp).
struct Goal {
  Eigen::Vector3d x_d;  ///< desired tip position (m)
  Vector6d q_d;         ///< desired joint positions (rad); only q_d[1] differs from q
  double kpx = 0;  ///< tip stiffness: acceleration per metre of x - x_d (1/s^2)
  double kvx = 0;  ///< tip damping: acceleration per m/s of dx (1/s)
  double kpj = 0;  ///< joint stiffness: acceleration per radian of q - q_d (1/s^2)
  double kvj = 0;  ///< joint damping: acceleration per rad/s of dq (1/s)
};

/// The joint torques Gamma of control law `part`.
Vector6d control(Part part, const State& state, const Goal& goal);

}  // namespace opspace::hw2::p1b
