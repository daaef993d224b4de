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

}  // namespace

TaskSpace::TaskSpace(Eigen::Index task_dim, Eigen::Index dof)
    : Lambda(checked(task_dim, kMaxTaskDim, "the task dimension"), task_dim),
      Jbar(checked(dof, kMaxDof, "the number of joints"), task_dim),
      N(dof, dof),
      p(task_dim),
      Ainv_Jt(dof, task_dim),
      Lambda_inv(task_dim, task_dim),
      A_llt(dof),
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
  out.A_llt.solveInPlace(out.Ainv_Jt);

  // Lambda^-1 = J A^-1 J^T = Q diag(mu) Q^T;  Lambda = Q diag(1/mu_i, mu_i > tol mu_max) Q^T
  out.Lambda_inv.noalias() = J * out.Ainv_Jt;
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

  out.Jbar.noalias() = out.Ainv_Jt * out.Lambda;  // Jbar = A^-1 J^T Lambda
  out.N.setIdentity();
  out.N.noalias() -= out.Jbar * J;                 // N = I - Jbar J
  out.p.noalias() = out.Jbar.transpose() * g;      // p = Jbar^T g
}

}  // namespace opspace
