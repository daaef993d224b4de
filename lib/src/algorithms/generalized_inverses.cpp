// The generalized inverses of problem 1a (linalg.hpp): answers a 1a runner must not hold, so
// they are compiled apart from the helpers of linalg.cpp; each is its own section, so a runner
// holds only those it reaches (docs/grader.md, "The library's own answers").
#include <stdexcept>
#include <string>

#include "opspace/algorithms/linalg.hpp"
#include "../math/small_decompositions.hpp"

namespace opspace {

namespace {

std::string size_of(Eigen::Index rows, Eigen::Index cols) { return std::to_string(rows) + "x" + std::to_string(cols); }

// J# = W^-1 J^T (J W^-1 J^T)^+ for W symmetric positive definite (Cholesky W = L L^T), shared
// by J# and Jbar (W = A) without either holding the other: `who` and `weight` name them in errors.
Eigen::MatrixXd weighted_right_inverse(const Eigen::Ref<const Eigen::MatrixXd>& J,
                                       const Eigen::Ref<const Eigen::MatrixXd>& W, double tol,
                                       const std::string& who, const std::string& weight) {
  require_finite(J, who + ": J");
  require_finite(W, who + ": " + weight);
  const Eigen::Index n = J.cols();
  require_size(W, n, n, who + ": " + weight + " (J is " + size_of(J.rows(), n) + ")");
  const double scale = W.cwiseAbs().maxCoeff();
  if (!(W - W.transpose()).isZero(1e-12 * (scale > 0 ? scale : 1.0))) {
    throw std::invalid_argument(who + ": " + weight + " is not symmetric");
  }
  Eigen::MatrixXd L = W;
  if (!detail::cholesky_in_place(L)) {
    throw std::invalid_argument(who + ": " + weight + " is not positive definite");
  }
  Eigen::MatrixXd Winv_Jt = J.transpose();
  detail::cholesky_solve_in_place(L, Winv_Jt);  // W^-1 J^T
  return Winv_Jt.lazyProduct(symmetric_pseudo_inverse(J.lazyProduct(Winv_Jt), tol));
}

}  // namespace

Eigen::MatrixXd pseudo_inverse(const Eigen::Ref<const Eigen::MatrixXd>& J, double tol) {
  require_finite(J, "pseudo_inverse: J");
  // J = U S V^T  =>  J+ = V S+ U^T
  const Svd d = svd(J, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = d.sigma;
  const double cutoff = s.size() > 0 ? tol * s(0) : 0.0;
  Eigen::VectorXd s_inv = Eigen::VectorXd::Zero(s.size());
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    if (s(i) > cutoff && s(i) > 0.0) s_inv(i) = 1.0 / s(i);
  }
  return (d.V * s_inv.asDiagonal()).lazyProduct(d.U.transpose());
}

Eigen::MatrixXd weighted_inverse(const Eigen::Ref<const Eigen::MatrixXd>& J,
                                 const Eigen::Ref<const Eigen::MatrixXd>& W, double tol) {
  return weighted_right_inverse(J, W, tol, "weighted_inverse", "W");
}

Eigen::MatrixXd dynamically_consistent_inverse(const Eigen::Ref<const Eigen::MatrixXd>& J,
                                               const Eigen::Ref<const Eigen::MatrixXd>& A,
                                               double tol) {
  return weighted_right_inverse(J, A, tol, "dynamically_consistent_inverse", "A");
}

Eigen::MatrixXd nullspace_projector(const Eigen::Ref<const Eigen::MatrixXd>& J,
                                    const Eigen::Ref<const Eigen::MatrixXd>& J_inv) {
  require_size(J_inv, J.cols(), J.rows(),
               "nullspace_projector: J_inv (J is " + size_of(J.rows(), J.cols()) + ")");
  return Eigen::MatrixXd::Identity(J.cols(), J.cols()) - J_inv.lazyProduct(J);
}

}  // namespace opspace
