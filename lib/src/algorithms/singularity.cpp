#include "opspace/algorithms/singularity.hpp"

#include <stdexcept>
#include <string>

#include "opspace/algorithms/kinematics.hpp"
#include "opspace/algorithms/linalg.hpp"

namespace opspace {

namespace {

using Matrix3Xd = Eigen::Matrix<double, 3, Eigen::Dynamic>;

// Orthonormal basis of the null space of Jv (n x k, k = n - rank) and sigma_max(Jv).
struct NullSpace {
  Eigen::MatrixXd basis;
  double sigma_max = 0.0;
};

NullSpace null_space(const Eigen::Ref<const Matrix3Xd>& Jv, double tol) {
  const Svd d = svd(Jv, Eigen::ComputeFullV);
  const Eigen::VectorXd& s = d.sigma;
  NullSpace out;
  out.sigma_max = s.size() > 0 ? s(0) : 0.0;
  Eigen::Index rank = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i) rank += s(i) > tol * out.sigma_max ? 1 : 0;
  out.basis = d.V.rightCols(Jv.cols() - rank);
  return out;
}

void require_hessians(const Eigen::Ref<const Eigen::MatrixXd>& H, Eigen::Index n, const std::string& what) {
  require_size(H, 3 * n, n, what + ": H (3n x n stacked Hessians)");
  require_finite(H, what + ": H");
}

// C_u = N^T H_u N, the curvature of the tip along u over the self-motions (columns of N).
// Coefficient-based products: these matrices are at most n x n, and Eigen's blocked product
// would cost a build seconds for nothing (docs/performance.md).
Eigen::MatrixXd curvature_on(const Eigen::MatrixXd& N, const Eigen::Ref<const Eigen::MatrixXd>& H,
                             const Eigen::Vector3d& u) {
  const Eigen::MatrixXd Hu = directional_hessian(H, u);
  const Eigen::MatrixXd Hu_N = Hu.lazyProduct(N);
  return N.transpose().lazyProduct(Hu_N);
}

}  // namespace

Directions3 directions(const Eigen::Ref<const Matrix3Xd>& J, double tol) {
  require_finite(J, "directions: J");
  Directions3 d;
  if (J.cols() == 0) return d;  // nothing moves: every direction is singular, U = I
  const Svd j = svd(J, Eigen::ComputeFullU);
  const Eigen::VectorXd& s = j.sigma;  // min(3, n) values, decreasing
  d.U = j.U;
  d.sigma.head(s.size()) = s;
  for (Eigen::Index i = 0; i < s.size(); ++i) d.rank += s(i) > tol * s(0) ? 1 : 0;
  return d;
}

Eigen::MatrixXd directional_hessian(const Eigen::Ref<const Eigen::MatrixXd>& H, const Eigen::Vector3d& u) {
  const Eigen::Index n = H.cols();
  require_size(H, 3 * n, n, "directional_hessian: H");
  return u(0) * H.topRows(n) + u(1) * H.middleRows(n, n) + u(2) * H.bottomRows(n);
}

double self_motion_curvature(const Eigen::Ref<const Matrix3Xd>& Jv, const Eigen::Ref<const Eigen::MatrixXd>& H,
                             const Eigen::Vector3d& u, double tol) {
  require_finite(Jv, "self_motion_curvature: Jv");
  require_hessians(H, Jv.cols(), "self_motion_curvature");
  const NullSpace ns = null_space(Jv, tol);
  if (ns.basis.cols() == 0) return 0.0;
  return svd(curvature_on(ns.basis, H, u), 0).sigma(0);  // ||C_u||_2
}

SingularityType singularity_type(const Eigen::Ref<const Matrix3Xd>& Jv, const Eigen::Ref<const Eigen::MatrixXd>& H,
                                 const Eigen::Vector3d& u, double tol) {
  require_finite(Jv, "singularity_type: Jv");
  const double sigma_max = directions(Jv, tol).sigma(0);
  if ((Jv.transpose() * u).norm() > tol * sigma_max * u.norm()) return SingularityType::kNone;
  return self_motion_curvature(Jv, H, u, tol) > tol * sigma_max ? SingularityType::kTypeI
                                                                 : SingularityType::kTypeII;
}

SingularityAnalysis analyse_singularities(const Eigen::Ref<const Matrix3Xd>& Jv, const Eigen::Ref<const Matrix3Xd>& Jw,
                                          const Eigen::Ref<const Eigen::MatrixXd>& H, double tol) {
  const Eigen::Index n = Jv.cols();
  require_size(Jw, 3, n, "analyse_singularities: Jw");
  require_hessians(H, n, "analyse_singularities");
  SingularityAnalysis a;
  a.linear = directions(Jv, tol);
  a.angular = directions(Jw, tol);
  const int m = 3 - a.linear.rank;  // singular directions
  if (m == 0) return a;
  const NullSpace ns = null_space(Jv, tol);
  const Eigen::Index k = ns.basis.cols();
  if (k == 0) return a;  // no self-motion: every singular direction is Type II
  // L: u -> vec(C_u) on the singular subspace, one column per singular direction u_j.
  const Eigen::Matrix<double, 3, Eigen::Dynamic> Us = a.linear.singular();
  Eigen::MatrixXd L(k * k, m);
  for (int j = 0; j < m; ++j) {
    const Eigen::MatrixXd C = curvature_on(ns.basis, H, Us.col(j));
    L.col(j) = Eigen::Map<const Eigen::VectorXd>(C.data(), k * k);
  }
  // Right singular vectors of L, by decreasing singular value: those above the tolerance span
  // the Type I directions, the rest (the kernel of L) the Type II directions.
  const Svd l = svd(L, Eigen::ComputeFullV);
  const Eigen::VectorXd& s = l.sigma;
  for (Eigen::Index i = 0; i < s.size(); ++i) a.type_one += s(i) > tol * ns.sigma_max ? 1 : 0;
  a.linear.U.rightCols(m) = Us.lazyProduct(l.V);
  return a;
}

SingularityAnalysis analyse_singularities(const Model& model, Data& data, int frame, const Eigen::Vector3d& p,
                                          const Eigen::Ref<const Eigen::VectorXd>& q, double tol) {
  forward_kinematics(model, data, q);
  const Eigen::Index n = model.dof();
  Matrix6Xd J0(6, n);
  point_jacobian(model, data, frame, p, J0);
  Eigen::MatrixXd H(3 * n, n);
  point_position_hessian(model, data, frame, p, H);
  return analyse_singularities(J0.topRows<3>(), J0.bottomRows<3>(), H, tol);
}

}  // namespace opspace
