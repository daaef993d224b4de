#include "opspace/linalg.hpp"

#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "small_decompositions.hpp"

namespace opspace {

namespace {

std::string size_of(Eigen::Index rows, Eigen::Index cols) {
  std::ostringstream s;
  s << rows << "x" << cols;
  return s.str();
}

}  // namespace

void require_finite(const Eigen::Ref<const Eigen::MatrixXd>& M, const std::string& what) {
  if (!M.allFinite()) {
    throw std::invalid_argument(what + " holds NaN or inf");
  }
}

void require_size(const Eigen::Ref<const Eigen::MatrixXd>& M, Eigen::Index rows,
                  Eigen::Index cols, const std::string& what) {
  if (M.rows() != rows || M.cols() != cols) {
    throw std::invalid_argument(what + " is " + size_of(M.rows(), M.cols()) + ", expected " +
                                size_of(rows, cols));
  }
}

Svd svd(const Eigen::Ref<const Eigen::MatrixXd>& M, unsigned int options) {
  // One-sided Jacobi on the tall one of M and M^T, T (r x k, r >= k): T R = W with orthogonal
  // columns, so T = Uhat diag(sigma) R^T with sigma_j = |w_j| and Uhat_j = w_j / sigma_j. Then
  // M = T gives U = Uhat, V = R; M = T^T gives U = R, V = Uhat.
  const bool tall = M.rows() >= M.cols();
  Eigen::MatrixXd W = tall ? Eigen::MatrixXd(M) : Eigen::MatrixXd(M.transpose());
  const Eigen::Index r = W.rows(), k = W.cols();
  const double scale = detail::scale_to_unit(W);  // sigma is scaled back at the end
  // A column this small is zero to round-off: its direction is completed, not normalised.
  const double negligible = std::numeric_limits<double>::epsilon() * W.norm();
  Eigen::MatrixXd R;
  detail::orthogonalize_columns(W, R, negligible);
  Svd out;
  out.sigma = W.colwise().norm().transpose();
  Eigen::MatrixXd* const factors[] = {&W, &R};
  detail::sort_with_columns(out.sigma, true, factors);
  const bool want_u = (options & (Eigen::ComputeThinU | Eigen::ComputeFullU)) != 0;
  const bool want_v = (options & (Eigen::ComputeThinV | Eigen::ComputeFullV)) != 0;
  const bool full_hat = (options & (tall ? Eigen::ComputeFullU : Eigen::ComputeFullV)) != 0;
  if (tall ? want_u : want_v) {
    Eigen::MatrixXd Uhat(r, full_hat ? r : k);
    Eigen::Index valid = 0;
    while (valid < k && out.sigma(valid) > negligible) {
      Uhat.col(valid) = W.col(valid) / out.sigma(valid);
      ++valid;
    }
    detail::complete_orthonormal(Uhat, valid);
    (tall ? out.U : out.V) = std::move(Uhat);
  }
  if (tall ? want_v : want_u) (tall ? out.V : out.U) = std::move(R);
  out.sigma *= scale;
  return out;
}

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

Eigen::MatrixXd symmetric_pseudo_inverse(const Eigen::Ref<const Eigen::MatrixXd>& M,
                                         double tol) {
  require_finite(M, "symmetric_pseudo_inverse: M");
  if (M.rows() != M.cols()) {
    throw std::invalid_argument("symmetric_pseudo_inverse: M is " + size_of(M.rows(), M.cols()) +
                                ", expected a square matrix");
  }
  // M = Q D Q^T  =>  M+ = Q D+ Q^T (eigenvalues ascending; the last is the largest)
  Eigen::MatrixXd S = M, Q;
  Eigen::VectorXd d;
  detail::symmetric_eigen(S, d, Q, true);
  const double cutoff = d.size() > 0 ? tol * d(d.size() - 1) : 0.0;
  Eigen::VectorXd d_inv = Eigen::VectorXd::Zero(d.size());
  for (Eigen::Index i = 0; i < d.size(); ++i) {
    if (d(i) > cutoff && d(i) > 0.0) d_inv(i) = 1.0 / d(i);
  }
  return (Q * d_inv.asDiagonal()).lazyProduct(Q.transpose());
}

Eigen::MatrixXd weighted_inverse(const Eigen::Ref<const Eigen::MatrixXd>& J,
                                 const Eigen::Ref<const Eigen::MatrixXd>& W, double tol) {
  require_finite(J, "weighted_inverse: J");
  require_finite(W, "weighted_inverse: W");
  const Eigen::Index n = J.cols();
  require_size(W, n, n, "weighted_inverse: W (J is " + size_of(J.rows(), n) + ")");
  const double scale = W.cwiseAbs().maxCoeff();
  if (!(W - W.transpose()).isZero(1e-12 * (scale > 0 ? scale : 1.0))) {
    throw std::invalid_argument("weighted_inverse: W is not symmetric");
  }
  Eigen::MatrixXd L = W;
  if (!detail::cholesky_in_place(L)) {
    throw std::invalid_argument("weighted_inverse: W is not positive definite");
  }
  Eigen::MatrixXd Winv_Jt = J.transpose();
  detail::cholesky_solve_in_place(L, Winv_Jt);  // W^-1 J^T
  return Winv_Jt.lazyProduct(symmetric_pseudo_inverse(J.lazyProduct(Winv_Jt), tol));
}

Eigen::MatrixXd dynamically_consistent_inverse(const Eigen::Ref<const Eigen::MatrixXd>& J,
                                               const Eigen::Ref<const Eigen::MatrixXd>& A,
                                               double tol) {
  return weighted_inverse(J, A, tol);
}

Eigen::MatrixXd nullspace_projector(const Eigen::Ref<const Eigen::MatrixXd>& J,
                                    const Eigen::Ref<const Eigen::MatrixXd>& J_inv) {
  require_size(J_inv, J.cols(), J.rows(),
               "nullspace_projector: J_inv (J is " + size_of(J.rows(), J.cols()) + ")");
  return Eigen::MatrixXd::Identity(J.cols(), J.cols()) - J_inv.lazyProduct(J);
}

}  // namespace opspace
