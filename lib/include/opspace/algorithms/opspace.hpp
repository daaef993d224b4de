/// @file algorithms/opspace.hpp
/// The operational-space matrices of a task x with Jacobian J (m x n) on a robot with mass
/// matrix A (n x n) and gravity torques g (problem set 2, problems 1b-3):
///
///   Lambda = (J A^-1 J^T)^-1      task inertia
///   Jbar   = A^-1 J^T Lambda      dynamically consistent inverse of J
///   N      = I - Jbar J           null-space projector; N^T acts on torques
///   p      = Jbar^T g             gravity seen at the task
///
/// Source: O. Khatib, "A unified approach for motion and force control of robot manipulators:
/// the operational space formulation", IEEE Journal of Robotics and Automation 3(1), 1987,
/// where Lambda, Jbar and p are defined and Jbar is shown to be the inverse of J consistent with
/// the dynamics; the problem set's equations for problems 1b-3 use them as above.
///
/// Singularity-robust: Lambda^-1 = J A^-1 J^T is symmetric positive semi-definite, and its
/// eigenvalues mu_i <= tol * mu_max are dropped from the inverse instead of being inverted.
/// Near a singularity Lambda therefore stays finite (the task inertia along the singular
/// direction is set to zero: no force is commanded along it) and Jbar, N and p stay finite.
/// The default tolerance 1e-6 bounds the condition number of the inverted part at 1e6.
#pragma once

#include <Eigen/Core>

namespace opspace {

/// Default relative eigenvalue cut-off of the robust task inertia (see the file comment).
inline constexpr double kTaskInertiaTolerance = 1e-6;

/// Largest task (a full 6-D pose) and largest robot that TaskSpace holds. With these bounds
/// every matrix, and every temporary of the factorisations, lives on the stack.
inline constexpr int kMaxTaskDim = 6;
inline constexpr int kMaxDof = 12;

using TaskMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxTaskDim, kMaxTaskDim>;
using TaskVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxTaskDim, 1>;
using JointTaskMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDof, kMaxTaskDim>;
using JointMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDof, kMaxDof>;

/// Workspace and results of operational_space() for an m-dimensional task (m <= 6) on an
/// n-DOF robot (n <= 12). Never allocates on the heap.
struct TaskSpace {
  /// Throws std::invalid_argument if task_dim or dof is out of range.
  TaskSpace(Eigen::Index task_dim, Eigen::Index dof);

  TaskMatrix Lambda;           ///< m x m task inertia
  JointTaskMatrix Jbar;        ///< n x m dynamically consistent inverse
  JointMatrix N;               ///< n x n null-space projector I - Jbar J
  TaskVector p;                ///< m     gravity at the task, Jbar^T g
  Eigen::Index rank = 0;       ///< eigenvalues of J A^-1 J^T kept in the inverse
  JointTaskMatrix Ainv_Jt;     ///< n x m A^-1 J^T
  TaskMatrix Lambda_inv;       ///< m x m J A^-1 J^T

  // The robust path. When |Lambda^-1|_F |Lambda|_F < 1 / tol (well away from a singularity,
  // where every eigenvalue is kept) Lambda comes from a Cholesky factorisation of Lambda^-1,
  // and the three members below are not updated; otherwise from the eigen-decomposition
  // Lambda^-1 = Q diag(mu) Q^T (Jacobi rotations, mu ascending).
  TaskMatrix eigenvectors;  ///< Q
  TaskVector eigenvalues;   ///< mu
  /// 1 / mu_i for the eigenvalues kept, 0 for those dropped
  TaskVector inverse_eigenvalues;
};

/// Lambda, Jbar, N and p of task Jacobian J for mass matrix A and gravity torques g.
/// Throws std::invalid_argument if the sizes do not match `out` or A is not positive definite.
void operational_space(const Eigen::Ref<const Eigen::MatrixXd>& A,
                       const Eigen::Ref<const Eigen::MatrixXd>& J,
                       const Eigen::Ref<const Eigen::VectorXd>& g, TaskSpace& out,
                       double tol = kTaskInertiaTolerance);

}  // namespace opspace
