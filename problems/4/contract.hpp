/// @file problems/4/contract.hpp
/// (included by its path, <problems/4/contract.hpp>; the build copies it under the same path for
/// the grader's sandboxed compiler, which sees the contracts and the library's headers only)
/// Problem 4: the singularities of the 3R elbow arm (robots/rrr.urdf), analysed (questions
/// i-iv) and controlled (question v). Declared here, written by the student in
/// exercises/p4.cpp, by the instructor in solutions/p4.cpp.
#pragma once

#include <Eigen/Dense>  // everything a student may need: JacobiSVD, eigen solvers, inverse()
#include <array>

#include "opspace/algorithms/singularity.hpp"  // SingularityType, kSingularValueTolerance
#include "opspace/math/constants.hpp"          // kPi

namespace opspace::hw2::p4 {

using opspace::SingularityType;

/// sigma_i <= kTolerance * sigma_max counts as a vanishing singular value.
inline constexpr double kTolerance = opspace::kSingularValueTolerance;
/// Question v: the elbow angle of the retracted arm, the minimum of the potential for Z0 (rad):
/// 90 deg.
inline constexpr double kRetractedElbow = kPi / 2.0;
/// Question v: the angle joint 1 is driven to for Y0 (rad): 90 deg.
inline constexpr double kTurnedJoint1 = kPi / 2.0;

/// The tip's kinematics at one configuration, computed by the library (base frame {0}).
struct Kinematics {
  Eigen::Vector3d q;        ///< joint angles (rad)
  Eigen::Vector3d x;        ///< tip position (m)
  Eigen::Matrix3d Jv;       ///< linear Jacobian of the tip: v = Jv dq
  Eigen::Matrix3d Jw;       ///< angular Jacobian of the tip's link (end-effector): w = Jw dq
  /// Hessians of the tip coordinates: H[k](i, j) = d^2 x_k / dq_i dq_j (k = 0, 1, 2 for
  /// X0, Y0, Z0). The tip accelerates by xdd_k = Jv.row(k) qdd + dq^T H[k] dq.
  std::array<Eigen::Matrix3d, 3> H;
};

/// A set of orthonormal directions in {0}: the first `count` columns of `u`.
struct Directions {
  int count = 0;                                ///< how many directions (0 to 3)
  Eigen::Matrix3d u = Eigen::Matrix3d::Zero();  ///< unit directions in its first `count` columns
};

/// Up to three vectors of R^3 as columns, e.g. the basis Nb of the self-motions in iv. Its size is
/// bounded by 3x3, so its products are computed coefficient by coefficient: an Eigen::MatrixXd
/// works too, but its general matrix product adds about 2 s to every compile of this file.
using Basis3 = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3>;

/// i. How many degrees of freedom the tip has for positioning: the rank of Jv.
int degrees_of_freedom(const Kinematics& k);

/// ii. The singular directions: an orthonormal basis of the directions u with u^T Jv = 0.
Directions singular_directions(const Kinematics& k);

/// iii. The linear directions orthogonal to the singular ones (the tip can move along them).
Directions moving_directions(const Kinematics& k);

/// iii. The axes the tip can rotate about: an orthonormal basis of range(Jw).
Directions rotation_axes(const Kinematics& k);

/// iv. kNone if u (unit) is not a singular direction; kTypeI if some self-motion dq_n
/// (Jv dq_n = 0) moves the tip along u at second order (dq_n^T H_u dq_n != 0 with
/// H_u = sum_k u_k H[k]); kTypeII otherwise.
SingularityType singularity_type(const Kinematics& k, const Eigen::Vector3d& u);

/// Question v: which singular direction the tip must move along.
enum class Target {
  kAlongZ0 = 1,  ///< elbow lock: down along Z0
  kAlongY0 = 2,  ///< overhead lock: along Y0
};

/// What the controller knows at one tick, computed by the library from (q, dq).
struct State {
  double t = 0.0;              ///< time (s)
  Eigen::Vector3d q;           ///< joint angles (rad)
  Eigen::Vector3d dq;          ///< joint velocities (rad/s)
  Eigen::Vector3d x;           ///< tip position (m)
  Eigen::Vector3d dx;          ///< tip velocity (m/s)
  Eigen::Matrix3d Jv;          ///< tip Jacobian: dx = Jv dq
  Eigen::Matrix3d A;           ///< joint-space mass matrix
  Eigen::Vector3d g;           ///< gravity torques
  /// Singularity-robust task quantities: the eigenvalues of Lambda_v^-1 = Jv A^-1 Jv^T below
  /// scenarios::p4::kRobustTolerance times the largest are dropped, so near a singularity
  /// Lambda_v commands no force along the (nearly) singular directions, and N lets the
  /// self-motion torques act along them.
  Eigen::Matrix3d Lambda_v;    ///< task inertia
  Eigen::Matrix3d Jbar_v;      ///< dynamically consistent inverse A^-1 Jv^T Lambda_v
  Eigen::Matrix3d N;           ///< null-space projector I - Jbar_v Jv (N^T acts on torques)
  Eigen::Vector3d p;           ///< gravity at the tip, Jbar_v^T g
};

/// The target and gains (values in problems/4/run/scenario.hpp).
struct Goal {
  Eigen::Vector3d x_d;  ///< desired tip position (m)
  double kpx = 0;  ///< tip stiffness: acceleration per metre of x - x_d (1/s^2)
  double kvx = 0;  ///< tip damping: acceleration per m/s of dx (1/s)
  double kpj = 0;  ///< stiffness of the self-motion potential: acceleration per radian (1/s^2)
  double kvj = 0;  ///< joint damping: acceleration per rad/s of dq (1/s)
};

/// v. The joint torques that move the tip to goal.x_d along the singular direction `target`.
Eigen::Vector3d control(Target target, const State& state, const Goal& goal);

}  // namespace opspace::hw2::p4
