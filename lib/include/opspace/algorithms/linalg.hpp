/// @file algorithms/linalg.hpp
/// Generalized inverses and null-space projectors of a task Jacobian J (m x n, m <= n).
///
/// Conventions (problem set, problem 1a):
///   J+   = J^T (J J^T)^-1                   Moore-Penrose pseudo-inverse
///   J#   = W^-1 J^T (J W^-1 J^T)^-1         W-weighted right inverse (W symmetric positive definite)
///   Jbar = A^-1 J^T (J A^-1 J^T)^-1         dynamically consistent inverse (W = A, the mass matrix)
///   N    = I - J_inv J                      null-space projector of any right inverse J_inv
///
/// Sources: R. Penrose, "A generalized inverse for matrices", Proc. Cambridge Philosophical
/// Society 51, 1955 (J+); O. Khatib, IEEE Journal of Robotics and Automation 3(1), 1987, the
/// operational space formulation (Jbar, the inverse consistent with the dynamics); the problem
/// set's problem 1a (J#, and the three projectors compared).
///
/// Rank deficiency: a singular value sigma_i <= tol * sigma_max counts as zero and is dropped
/// from the inverse (it is not inverted). The result is then finite: J J_inv becomes the
/// orthogonal projector onto range(J) instead of I. The functions never return inf or NaN for
/// finite input; input that already holds NaN or inf is rejected with std::invalid_argument.
#pragma once

#include <Eigen/Core>
#include <string>

namespace opspace {

/// Default relative tolerance of the SVD-based inverses: sigma_i <= kSvdTolerance * sigma_max
/// is treated as zero. 1e-10 sits well above round-off (about 1e-15 * sigma_max) and well below
/// the smallest physical singular value of the course's robots away from singularities.
inline constexpr double kSvdTolerance = 1e-10;

/// Singular value decomposition M = U diag(sigma) V^T, sigma (min(rows, cols)) decreasing; U and
/// V as `options` asks (Eigen::ComputeFullU, ComputeThinU, ComputeFullV, ComputeThinV; empty
/// when not asked; Eigen's options, Eigen's conventions). One-sided Jacobi rotations: accurate
/// for the small matrices of the course, and compiled once here, where each instance of
/// Eigen::JacobiSVD is a large part of a build (docs/performance.md). A singular value at
/// round-off (<= eps |M|_F) gets a unit singular vector orthogonal to the others.
struct Svd {
  Eigen::MatrixXd U;
  Eigen::VectorXd sigma;
  Eigen::MatrixXd V;
};
Svd svd(const Eigen::Ref<const Eigen::MatrixXd>& M, unsigned int options);

/// Moore-Penrose pseudo-inverse by SVD: J+ = V S+ U^T, with S+ inverting sigma_i > tol * sigma_max.
Eigen::MatrixXd pseudo_inverse(const Eigen::Ref<const Eigen::MatrixXd>& J,
                               double tol = kSvdTolerance);

/// Inverse of a symmetric positive semi-definite matrix M through its eigen-decomposition,
/// dropping eigenvalues <= tol * lambda_max (the robust inverse used for J W^-1 J^T).
Eigen::MatrixXd symmetric_pseudo_inverse(const Eigen::Ref<const Eigen::MatrixXd>& M,
                                         double tol = kSvdTolerance);

/// W-weighted right inverse J# = W^-1 J^T (J W^-1 J^T)^-1.
/// Throws std::invalid_argument if W is not n x n, not symmetric or not positive definite.
/// A rank-deficient J gives (J W^-1 J^T)^+ in place of the inverse (see the file comment).
Eigen::MatrixXd weighted_inverse(const Eigen::Ref<const Eigen::MatrixXd>& J,
                                 const Eigen::Ref<const Eigen::MatrixXd>& W,
                                 double tol = kSvdTolerance);

/// Dynamically consistent (inertia-weighted) inverse Jbar = A^-1 J^T (J A^-1 J^T)^-1,
/// i.e. weighted_inverse(J, A) with the mass matrix A as the weight.
Eigen::MatrixXd dynamically_consistent_inverse(const Eigen::Ref<const Eigen::MatrixXd>& J,
                                               const Eigen::Ref<const Eigen::MatrixXd>& A,
                                               double tol = kSvdTolerance);

/// Null-space projector N = I - J_inv J (n x n) for a right inverse J_inv (n x m) of J (m x n).
/// N^T = I - J^T J_inv^T is the projector that acts on joint torques.
Eigen::MatrixXd nullspace_projector(const Eigen::Ref<const Eigen::MatrixXd>& J,
                                    const Eigen::Ref<const Eigen::MatrixXd>& J_inv);

/// Throws std::invalid_argument naming `what` if M holds a NaN or an infinity.
void require_finite(const Eigen::Ref<const Eigen::MatrixXd>& M, const std::string& what);

/// Throws std::invalid_argument naming `what` and both sizes unless M is rows x cols.
void require_size(const Eigen::Ref<const Eigen::MatrixXd>& M, Eigen::Index rows,
                  Eigen::Index cols, const std::string& what);

}  // namespace opspace
