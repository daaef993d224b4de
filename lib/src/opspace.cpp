#include "opspace/opspace.hpp"

#include <stdexcept>
#include <string>

#include "opspace/linalg.hpp"

namespace opspace {

namespace {

Eigen::Index checked(Eigen::Index value, Eigen::Index max, const char* what) {
  if (value < 1 || value > max) {
    throw std::invalid_argument(std::string("TaskSpace: ") + what + " is " + std::to_string(value) +
                                ", expected 1 to " + std::to_string(max));
  }
  return value;
}

/// X <- (L L^T)^-1 X for the Cholesky factor L held in the lower triangle of LL, column by
/// column with plain loops: at these sizes (n <= 12) Eigen's triangular-solve kernels cost
/// several times more in dispatch than in arithmetic (callgrind, docs/performance.md).
template <typename Factor, typename Rhs>
void cholesky_solve_in_place(const Factor& LL, Rhs& X) {
  const Eigen::Index n = LL.rows();
  for (Eigen::Index c = 0; c < X.cols(); ++c) {
    for (Eigen::Index i = 0; i < n; ++i) {  // L y = x
      double s = X(i, c);
      for (Eigen::Index j = 0; j < i; ++j) s -= LL(i, j) * X(j, c);
      X(i, c) = s / LL(i, i);
    }
    for (Eigen::Index i = n - 1; i >= 0; --i) {  // L^T x = y
      double s = X(i, c);
      for (Eigen::Index j = i + 1; j < n; ++j) s -= LL(j, i) * X(j, c);
      X(i, c) = s / LL(i, i);
    }
  }
}

/// C <- C + sign * A B with plain loops (small matrices, as above).
template <typename MA, typename MB, typename MC>
void add_product(const MA& A, const MB& B, MC& C, double sign) {
  for (Eigen::Index c = 0; c < C.cols(); ++c) {
    for (Eigen::Index k = 0; k < A.cols(); ++k) {
      const double b = sign * B(k, c);
      for (Eigen::Index r = 0; r < C.rows(); ++r) C(r, c) += A(r, k) * b;
    }
  }
}

/// Fast path of the robust inverse: Lambda = (Lambda^-1)^-1 by Cholesky, kept only when no
/// eigenvalue of Lambda^-1 can fall below tol * mu_max. Since mu_max <= |Lambda^-1|_F and
/// 1 / mu_min = |Lambda|_2 <= |Lambda|_F, |Lambda^-1|_F |Lambda|_F < 1 / tol guarantees
/// mu_min > tol * mu_max: the eigen-decomposition would keep every eigenvalue and give the
/// same Lambda, at several times the cost. Returns false (Lambda unspecified) otherwise.
/// out.eigen and out.inverse_eigenvalues are then left untouched.
bool invert_well_conditioned(TaskSpace& out, double tol) {
  out.task_llt.compute(out.Lambda_inv);
  if (out.task_llt.info() != Eigen::Success) return false;
  out.Lambda.setIdentity();
  cholesky_solve_in_place(out.task_llt.matrixLLT(), out.Lambda);
  if (!(out.Lambda_inv.norm() * out.Lambda.norm() * tol < 1.0)) return false;  // also catches NaN
  out.rank = out.Lambda.rows();
  return true;
}

}  // namespace

TaskSpace::TaskSpace(Eigen::Index task_dim, Eigen::Index dof)
    : Lambda(checked(task_dim, kMaxTaskDim, "the task dimension"), task_dim),
      Jbar(checked(dof, kMaxDof, "the number of joints"), task_dim),
      N(dof, dof),
      p(task_dim),
      Ainv_Jt(dof, task_dim),
      Lambda_inv(task_dim, task_dim),
      A_llt(dof),
      task_llt(task_dim),
      eigen(task_dim),
      inverse_eigenvalues(task_dim) {}

void operational_space(const Eigen::Ref<const Eigen::MatrixXd>& A,
                       const Eigen::Ref<const Eigen::MatrixXd>& J,
                       const Eigen::Ref<const Eigen::VectorXd>& g, TaskSpace& out, double tol) {
  const Eigen::Index m = out.Lambda.rows(), n = out.N.rows();
  if (J.rows() != m || J.cols() != n || A.rows() != n || A.cols() != n || g.size() != n) {
    require_size(J, m, n, "operational_space: J");  // the messages are built only on failure
    require_size(A, n, n, "operational_space: A");
    require_size(g, n, 1, "operational_space: g");
  }

  // A^-1 J^T by Cholesky
  out.A_llt.compute(A);
  if (out.A_llt.info() != Eigen::Success) {
    throw std::invalid_argument("operational_space: A is not positive definite");
  }
  out.Ainv_Jt = J.transpose();
  cholesky_solve_in_place(out.A_llt.matrixLLT(), out.Ainv_Jt);

  out.Lambda_inv.setZero();
  add_product(J, out.Ainv_Jt, out.Lambda_inv, 1.0);  // Lambda^-1 = J A^-1 J^T
  if (!invert_well_conditioned(out, tol)) {
    // Lambda^-1 = Q diag(mu) Q^T;  Lambda = Q diag(1/mu_i, mu_i > tol mu_max) Q^T
    out.eigen.compute(out.Lambda_inv);
    const auto& mu = out.eigen.eigenvalues();  // ascending
    const double cutoff = tol * mu(m - 1);
    out.rank = 0;
    for (Eigen::Index i = 0; i < m; ++i) {
      const bool kept = mu(i) > cutoff && mu(i) > 0.0;
      out.inverse_eigenvalues(i) = kept ? 1.0 / mu(i) : 0.0;
      out.rank += kept ? 1 : 0;
    }
    const auto& Q = out.eigen.eigenvectors();
    out.Lambda.noalias() = Q * out.inverse_eigenvalues.asDiagonal() * Q.transpose();
  }

  out.Jbar.setZero();
  add_product(out.Ainv_Jt, out.Lambda, out.Jbar, 1.0);  // Jbar = A^-1 J^T Lambda
  out.N.setIdentity();
  add_product(out.Jbar, J, out.N, -1.0);             // N = I - Jbar J
  out.p.noalias() = out.Jbar.transpose() * g;      // p = Jbar^T g
}

}  // namespace opspace
