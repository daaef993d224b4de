// The linear algebra the library's algorithms share: argument checks, the SVD and the symmetric
// pseudo-inverse. The generalized inverses of problem 1a are in generalized_inverses.cpp, apart:
// a runner that calls one of these (allowed everywhere) never links an answer of problem 1a
// (docs/grader.md, "The library's own answers").
#include "opspace/algorithms/linalg.hpp"

#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "../math/small_decompositions.hpp"

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

}  // namespace opspace
