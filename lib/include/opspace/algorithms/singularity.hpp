/// @file algorithms/singularity.hpp
/// Singularities of a point's positioning task (problem 4): which directions a point can move
/// along, which it cannot, and of which type each blocked direction is. Source: the problem
/// set's problem 4 (singular directions from the SVD of Jv, Type I and Type II by the second-
/// order motion along each); the SVD is linalg.hpp's.
///
/// Directions. The SVD J = U diag(sigma) V^T of a 3 x n Jacobian (Jv: linear, Jw: angular)
/// splits R^3 at the tolerance: sigma_i > tol * sigma_max counts as non-zero. The first `rank`
/// columns of U span range(J), the directions the point can move along (or rotate about); the
/// remaining columns, left singular vectors of vanishing singular values, span the singular
/// directions u with u^T J = 0: no joint velocity moves the point along them.
///
/// Types (linear singular directions). With u^T Jv = 0, the motion along u is of second order:
///   u^T xdd = u^T Jv qdd + qdot^T H_u qdot = qdot^T H_u qdot,   H_u = d^2 (u . x) / dq^2.
/// A self-motion qdot = dq_n (Jv dq_n = 0: the point does not move at first order) moves the
/// point along u at second order iff dq_n^T H_u dq_n != 0. Restricted to the null space of Jv
/// (orthonormal basis Nb, n x k), the quadratic form is C_u = Nb^T H_u Nb (k x k):
///   Type I  (C_u != 0): some internal motion moves the point along u directly; a potential
///                       whose minimum lies on that motion (e.g. a retracted arm) reaches u.
///   Type II (C_u == 0): no internal motion does; the singular direction itself must first be
///                       rotated (by joints that also move the point in range(Jv)).
/// C_u is linear in u, so within the singular subspace the Type II directions form the kernel
/// of u -> C_u, and its orthogonal complement holds the Type I directions: the split below
/// does not depend on the basis an SVD happens to return for repeated singular values.
/// "C_u != 0" means ||C_u||_2 > tol * sigma_max(Jv) (units 1/rad for revolute joints).
/// A robot without a null space (k = 0) has only Type II singular directions by this test.
#pragma once

#include <Eigen/Core>

#include "opspace/model/model.hpp"

namespace opspace {

/// Default relative tolerance of the singularity analysis: sigma_i <= tol * sigma_max counts
/// as zero. 1e-6 lies far above round-off (1e-16 * sigma_max, and cos(pi/2) = 6e-17 in double
/// precision) and far below the singular values of a configuration one would call regular
/// (on the 3R arm, 1e-6 relative is a tip within about a micrometre of the singular pose).
inline constexpr double kSingularValueTolerance = 1e-6;

/// Not singular, or the type of a singular direction (see the file comment).
enum class SingularityType { kNone = 0, kTypeI = 1, kTypeII = 2 };

/// The SVD of a 3 x n Jacobian, split at the tolerance.
struct Directions3 {
  Eigen::Matrix3d U = Eigen::Matrix3d::Identity();  ///< left singular vectors (columns)
  Eigen::Vector3d sigma = Eigen::Vector3d::Zero();  ///< singular values, decreasing
  int rank = 0;                                     ///< how many sigma_i > tol * sigma_max

  /// range(J): the directions the point moves along, orthogonal to the singular ones.
  Eigen::Block<const Eigen::Matrix3d, 3, Eigen::Dynamic, true> moving() const { return U.leftCols(rank); }
  /// The singular directions: u^T J = 0.
  Eigen::Block<const Eigen::Matrix3d, 3, Eigen::Dynamic, true> singular() const {
    return U.rightCols(3 - rank);
  }
};

/// Directions of J (3 x n) by its SVD. Allocates (an analysis, not a control tick).
/// Throws std::invalid_argument if J holds NaN or inf.
Directions3 directions(const Eigen::Ref<const Eigen::Matrix<double, 3, Eigen::Dynamic>>& J,
                       double tol = kSingularValueTolerance);

/// Hessians of the position x of point p on frame `frame`, stacked (3n x n):
/// H.middleRows(k n, n) = d^2 x_k / dq^2. With the columns [Jv_i; Jw_i] of the point Jacobian
/// and i <= j along the chain (i an ancestor of j or j itself),
///   d^2 x / dq_i dq_j = Jw_i x Jv_j,
/// because q_i rotates the whole subtree that carries joint j and the point about Jw_i
/// (a prismatic joint has Jw_i = 0). Call forward_kinematics() first.
void point_position_hessian(const Model& model, const Data& data, int frame,
                            const Eigen::Vector3d& p, Eigen::Ref<Eigen::MatrixXd> H);

/// H_u = sum_k u_k H_k (n x n): the Hessian of u . x, from the stacked Hessians H (3n x n).
Eigen::MatrixXd directional_hessian(const Eigen::Ref<const Eigen::MatrixXd>& H,
                                    const Eigen::Vector3d& u);

/// ||Nb^T H_u Nb||_2: how strongly the self-motions of Jv (3 x n) move the point along u at
/// second order (0 when Jv has no null space).
double self_motion_curvature(const Eigen::Ref<const Eigen::Matrix<double, 3, Eigen::Dynamic>>& Jv,
                             const Eigen::Ref<const Eigen::MatrixXd>& H, const Eigen::Vector3d& u,
                             double tol = kSingularValueTolerance);

/// kNone if |Jv^T u| > tol * sigma_max(Jv) |u| (u is not a singular direction), otherwise
/// kTypeI if self_motion_curvature(Jv, H, u) > tol * sigma_max(Jv), otherwise kTypeII.
SingularityType singularity_type(const Eigen::Ref<const Eigen::Matrix<double, 3, Eigen::Dynamic>>& Jv,
                                 const Eigen::Ref<const Eigen::MatrixXd>& H,
                                 const Eigen::Vector3d& u, double tol = kSingularValueTolerance);

/// The singularities of a point's pose.
struct SingularityAnalysis {
  /// Linear directions of Jv. Its singular columns are ordered Type I first: columns
  /// rank .. rank + type_one - 1 are Type I, the rest up to 2 are Type II.
  Directions3 linear;
  Directions3 angular;  ///< directions of Jw: rotations about moving() are possible
  int type_one = 0;     ///< how many linear singular directions are Type I

  /// Type of linear singular direction i (0 <= i < 3 - linear.rank).
  SingularityType type(int i) const {
    return i < type_one ? SingularityType::kTypeI : SingularityType::kTypeII;
  }
};

/// Analysis from Jv, Jw (3 x n each) and the stacked position Hessians H (3n x n).
/// Throws std::invalid_argument for mismatched sizes or non-finite input.
SingularityAnalysis analyse_singularities(const Eigen::Ref<const Eigen::Matrix<double, 3, Eigen::Dynamic>>& Jv,
                                          const Eigen::Ref<const Eigen::Matrix<double, 3, Eigen::Dynamic>>& Jw,
                                          const Eigen::Ref<const Eigen::MatrixXd>& H,
                                          double tol = kSingularValueTolerance);

/// Analysis of point p on frame `frame` at configuration q (runs forward_kinematics).
SingularityAnalysis analyse_singularities(const Model& model, Data& data, int frame,
                                          const Eigen::Vector3d& p,
                                          const Eigen::Ref<const Eigen::VectorXd>& q,
                                          double tol = kSingularValueTolerance);

}  // namespace opspace
