#include "opspace/linalg.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <sstream>
#include <stdexcept>

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
  const Eigen::JacobiSVD<Eigen::MatrixXd> d(M, options);
  Svd out;
  out.sigma = d.singularValues();
  if (d.computeU()) out.U = d.matrixU();
  if (d.computeV()) out.V = d.matrixV();
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
  return d.V * s_inv.asDiagonal() * d.U.transpose();
}

Eigen::MatrixXd symmetric_pseudo_inverse(const Eigen::Ref<const Eigen::MatrixXd>& M,
                                         double tol) {
  require_finite(M, "symmetric_pseudo_inverse: M");
  if (M.rows() != M.cols()) {
    throw std::invalid_argument("symmetric_pseudo_inverse: M is " + size_of(M.rows(), M.cols()) +
                                ", expected a square matrix");
  }
  // M = Q D Q^T  =>  M+ = Q D+ Q^T (eigenvalues ascending; the last is the largest)
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(M);
  const Eigen::VectorXd& d = eig.eigenvalues();
  const double cutoff = d.size() > 0 ? tol * d(d.size() - 1) : 0.0;
  Eigen::VectorXd d_inv = Eigen::VectorXd::Zero(d.size());
  for (Eigen::Index i = 0; i < d.size(); ++i) {
    if (d(i) > cutoff && d(i) > 0.0) d_inv(i) = 1.0 / d(i);
  }
  return eig.eigenvectors() * d_inv.asDiagonal() * eig.eigenvectors().transpose();
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
  const Eigen::LLT<Eigen::MatrixXd> llt(W);
  if (llt.info() != Eigen::Success) {
    throw std::invalid_argument("weighted_inverse: W is not positive definite");
  }
  const Eigen::MatrixXd Winv_Jt = llt.solve(J.transpose());  // W^-1 J^T
  return Winv_Jt * symmetric_pseudo_inverse(J * Winv_Jt, tol);
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
  return Eigen::MatrixXd::Identity(J.cols(), J.cols()) - J_inv * J;
}

}  // namespace opspace
