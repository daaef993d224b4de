#include "opspace/algorithms/opspace.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "opspace/algorithms/linalg.hpp"
#include "../math/small_decompositions.hpp"

namespace opspace {

namespace {

using Eigen::Index;

// The kernels below work on matrices whose sizes are template parameters: the factorisations
// are plain loops, the products Eigen's coefficient-based lazy products. For the task shapes
// of the course (6 x 7, 3 x 6, 3 x 3) the compiler unrolls and vectorises both, where Eigen's
// general-purpose LLT and blocked products, built for large matrices, spent most of their time
// in size dispatch (callgrind, docs/performance.md).

/// Linv = L^-1 for the lower-triangular L (in its lower triangle; `Linv` holds zeros above), by
/// forward substitution a row at a time: Linv_i = (e_i - sum_{k<i} L_ik Linv_k) / L_ii. With
/// Linv stored by rows, each step is a vector operation on a whole row.
template <typename Factor, typename Inverse>
void lower_inverse(const Factor& L, Inverse& Linv) {
  const Index n = L.rows();
  for (Index i = 0; i < n; ++i) {
    Linv(i, i) = 1.0;
    for (Index k = 0; k < i; ++k) Linv.row(i) -= L(i, k) * Linv.row(k);
    Linv.row(i) *= 1.0 / L(i, i);
  }
}

/// Column-major view of size Rows x Cols (compile-time where known) on a Ref's data.
template <int Rows, int Cols, typename Ref>
auto view(const Ref& X) {
  using Mat = Eigen::Matrix<double, Rows, Cols>;
  return Eigen::Map<const Mat, 0, Eigen::OuterStride<>>(X.data(), X.rows(), X.cols(),
                                                         Eigen::OuterStride<>(X.outerStride()));
}

/// The same for a TaskSpace member, whose storage is contiguous (leading dimension = rows).
template <int Rows, int Cols, typename Member>
auto view_mut(Member& X) {
  return Eigen::Map<Eigen::Matrix<double, Rows, Cols>>(X.data(), X.rows(), X.cols());
}

/// Lambda = (Lambda^-1)^-1 on the robust eigen path: Lambda^-1 = Q diag(mu) Q^T,
/// Lambda = Q diag(1/mu_i for mu_i > tol mu_max, else 0) Q^T.
void invert_robustly(TaskSpace& out, double tol) {
  const Index m = out.Lambda.rows();
  TaskMatrix S = out.Lambda_inv;
  detail::symmetric_eigen(S, out.eigenvalues, out.eigenvectors, true);
  const auto& mu = out.eigenvalues;  // ascending
  const double cutoff = tol * mu(m - 1);
  out.rank = 0;
  for (Index i = 0; i < m; ++i) {
    const bool kept = mu(i) > cutoff && mu(i) > 0.0;
    out.inverse_eigenvalues(i) = kept ? 1.0 / mu(i) : 0.0;
    out.rank += kept ? 1 : 0;
  }
  const auto& Q = out.eigenvectors;
  out.Lambda.noalias() = Q * out.inverse_eigenvalues.asDiagonal() * Q.transpose();
}

/// operational_space() for an M-dimensional task on an N-DOF robot (either may be
/// Eigen::Dynamic). Sizes are checked by the caller.
template <int M, int N>
void operational_space_sized(const Eigen::Ref<const Eigen::MatrixXd>& A_in,
                             const Eigen::Ref<const Eigen::MatrixXd>& J_in,
                             const Eigen::Ref<const Eigen::VectorXd>& g_in, TaskSpace& out, double tol) {
  constexpr int kMaxN = N == Eigen::Dynamic ? kMaxDof : N;
  constexpr int kMaxM = M == Eigen::Dynamic ? kMaxTaskDim : M;
  // Compile-time sizes where known: the loops of the factorisations then unroll.
  const Index m = M == Eigen::Dynamic ? out.Lambda.rows() : M;
  const Index n = N == Eigen::Dynamic ? out.N.rows() : N;
  const auto A = view<N, N>(A_in);
  const auto J = view<M, N>(J_in);
  const auto g = view<N, 1>(g_in);
  auto Ainv_Jt = view_mut<N, M>(out.Ainv_Jt);
  auto Lambda_inv = view_mut<M, M>(out.Lambda_inv);
  auto Lambda = view_mut<M, M>(out.Lambda);
  auto Jbar = view_mut<N, M>(out.Jbar);
  auto Nproj = view_mut<N, N>(out.N);
  auto p = view_mut<M, 1>(out.p);

  // A = L L^T;  W = L^-1 J^T;  Lambda^-1 = J A^-1 J^T = W^T W;  A^-1 J^T = L^-T W.
  using NxN = Eigen::Matrix<double, N, N, 0, kMaxN, kMaxN>;
  NxN L(n, n);
  L.template triangularView<Eigen::Lower>() = A;
  if (!detail::cholesky_in_place(L)) throw std::invalid_argument("operational_space: A is not positive definite");
  // The two triangular solves run by substitution a row at a time: each step is an operation
  // on a whole row of m task columns, which vectorises, and half of L^-1's products (its
  // zeros) are never made.  Forward:  W_i = (J^T_i - sum_{k<i} L_ik W_k) / L_ii.
  constexpr int kRowOrder = M == 1 ? Eigen::ColMajor : Eigen::RowMajor;
  using NxMRows = Eigen::Matrix<double, N, M, kRowOrder, kMaxN, kMaxM>;
  NxMRows W(n, m);
  for (Index i = 0; i < n; ++i) {
    W.row(i) = J.col(i).transpose();
    for (Index k = 0; k < i; ++k) W.row(i) -= L(i, k) * W.row(k);
    W.row(i) *= 1.0 / L(i, i);
  }
  Lambda_inv.noalias() = W.transpose().lazyProduct(W);
  // Backward:  (A^-1 J^T)_i = (W_i - sum_{k>i} L_ki (A^-1 J^T)_k) / L_ii.
  NxMRows X(n, m);
  for (Index i = n - 1; i >= 0; --i) {
    X.row(i) = W.row(i);
    for (Index k = i + 1; k < n; ++k) X.row(i) -= L(k, i) * X.row(k);
    X.row(i) *= 1.0 / L(i, i);
  }
  Ainv_Jt = X;

  // Fast path: Lambda = R^-T R^-1 with R = chol(Lambda^-1), kept only when no eigenvalue of
  // Lambda^-1 can fall below tol * mu_max. Since mu_max <= |Lambda^-1|_F and
  // 1 / mu_min = |Lambda|_2 <= |Lambda|_F, |Lambda^-1|_F |Lambda|_F < 1 / tol guarantees
  // mu_min > tol * mu_max: the eigen-decomposition would keep every eigenvalue and give the
  // same Lambda, at several times the cost. Otherwise (near a singularity) the robust path.
  using MxM = Eigen::Matrix<double, M, M, 0, kMaxM, kMaxM>;
  MxM R(m, m);
  // R^-1 kept by rows, so that R^-T R^-1 runs along contiguous rows (and vectorises).
  using MxMRows = Eigen::Matrix<double, M, M, kRowOrder, kMaxM, kMaxM>;
  MxMRows Rinv = MxMRows::Zero(m, m);
  R.template triangularView<Eigen::Lower>() = Lambda_inv;
  bool well_conditioned = detail::cholesky_in_place(R);
  if (well_conditioned) {
    lower_inverse(R, Rinv);
    Lambda.noalias() = Rinv.transpose().lazyProduct(Rinv);
    well_conditioned = Lambda_inv.norm() * Lambda.norm() * tol < 1.0;  // false for NaN too
  }
  if (well_conditioned) {
    out.rank = m;  // the eigen-decomposition members are left untouched
  } else {
    invert_robustly(out, tol);
  }

  // Jbar = A^-1 J^T Lambda, formed as Jbar^T = Lambda (A^-1 J^T)^T (Lambda is symmetric): the
  // product then runs down Lambda's columns, which vectorises.
  Eigen::Matrix<double, M, N, 0, kMaxM, kMaxN> JbarT(m, n);
  JbarT.noalias() = Lambda.lazyProduct(X.transpose());
  Jbar = JbarT.transpose();
  // N = I - Jbar J a column at a time, N_j = e_j - sum_a J_aj Jbar_a: whole columns of Jbar,
  // which vectorise for any joint count (a lazy product of 7 rows did not).
  for (Index j = 0; j < n; ++j) {
    auto Nj = Nproj.col(j);
    Nj.noalias() = -J(0, j) * Jbar.col(0);
    for (Index a = 1; a < m; ++a) Nj.noalias() -= J(a, j) * Jbar.col(a);
    Nj(j) += 1.0;
  }
  p.noalias() = JbarT.lazyProduct(g);  // p = Jbar^T g
}

}  // namespace

void operational_space(const Eigen::Ref<const Eigen::MatrixXd>& A,
                       const Eigen::Ref<const Eigen::MatrixXd>& J,
                       const Eigen::Ref<const Eigen::VectorXd>& g, TaskSpace& out, double tol) {
  const Index m = out.Lambda.rows(), n = out.N.rows();
  if (J.rows() != m || J.cols() != n || A.rows() != n || A.cols() != n || g.size() != n) {
    require_size(J, m, n, "operational_space: J");  // the messages are built only on failure
    require_size(A, n, n, "operational_space: A");
    require_size(g, n, 1, "operational_space: g");
  }
  // Compiled sizes for the tasks of the problem set: the iiwa's pose (problems 2 and 3), the
  // PUMA's tip position (1b) and the 3R arm's tip position (4).
  if (m == 6 && n == 7) return operational_space_sized<6, 7>(A, J, g, out, tol);
  if (m == 3 && n == 6) return operational_space_sized<3, 6>(A, J, g, out, tol);
  if (m == 3 && n == 3) return operational_space_sized<3, 3>(A, J, g, out, tol);
  operational_space_sized<Eigen::Dynamic, Eigen::Dynamic>(A, J, g, out, tol);
}

}  // namespace opspace
