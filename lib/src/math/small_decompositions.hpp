// Decompositions for the small matrices of the course (at most 12 x 12): Cholesky, the eigen-
// decomposition of a symmetric matrix by Jacobi rotations, and the one-sided Jacobi
// orthogonalisation behind the SVD (linalg.cpp). Plain loops over any Eigen matrix type: an
// instance compiles in a fraction of a second, where each instance of Eigen's general
// SelfAdjointEigenSolver and JacobiSVD cost 8 to 12 s of a student's first build
// (docs/performance.md). For fixed sizes the compiler unrolls and vectorises the loops. Jacobi
// methods are also the accurate ones for such matrices: eigenvalues and singular values come
// out with small relative error (Demmel and Veselic, "Jacobi's method is more accurate than
// QR", SIAM J. Matrix Anal. Appl. 13, 1992).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace opspace::detail {

/// A = L L^T: L overwrites the lower triangle of `L` (which holds A on entry; the strict upper
/// triangle is not read). False if A is not positive definite (or holds a NaN).
template <typename Mat>
bool cholesky_in_place(Mat& L) {
  const Eigen::Index n = L.rows();
  for (Eigen::Index j = 0; j < n; ++j) {
    double d = L(j, j);
    for (Eigen::Index k = 0; k < j; ++k) d -= L(j, k) * L(j, k);
    if (!(d > 0.0)) return false;
    const double ljj = std::sqrt(d);
    L(j, j) = ljj;
    for (Eigen::Index i = j + 1; i < n; ++i) {
      double s = L(i, j);
      for (Eigen::Index k = 0; k < j; ++k) s -= L(i, k) * L(j, k);
      L(i, j) = s / ljj;
    }
  }
  return true;
}

/// X <- (L L^T)^-1 X for the Cholesky factor L (lower triangle), by substitution a row of X at a
/// time: forward Y_i = (X_i - sum_{k<i} L_ik Y_k) / L_ii, then backward
/// X_i = (Y_i - sum_{k>i} L_ki X_k) / L_ii.
template <typename Factor, typename Mat>
void cholesky_solve_in_place(const Factor& L, Mat& X) {
  const Eigen::Index n = L.rows();
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index k = 0; k < i; ++k) X.row(i) -= L(i, k) * X.row(k);
    X.row(i) *= 1.0 / L(i, i);
  }
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    for (Eigen::Index k = i + 1; k < n; ++k) X.row(i) -= L(k, i) * X.row(k);
    X.row(i) *= 1.0 / L(i, i);
  }
}

inline constexpr int kMaxJacobiSweeps = 60;  // quadratic convergence: under 10 sweeps at 12 x 12

/// The rotation (c, s) that zeroes the off-diagonal entry of the symmetric 2 x 2 [[app, apq],
/// [apq, aqq]] as J^T [..] J with J = [[c, s], [-s, c]] (Golub and Van Loan, section 8.5.2):
/// theta = (aqq - app) / (2 apq), t = sign(theta) / (|theta| + sqrt(1 + theta^2)).
inline void jacobi_rotation(double app, double aqq, double apq, double& c, double& s) {
  const double theta = (aqq - app) / (2.0 * apq);
  const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(1.0 + theta * theta));
  c = 1.0 / std::sqrt(1.0 + t * t);
  s = t * c;
}

/// Divides X by its largest |entry| and returns that factor (1 for a zero matrix, or one with an
/// infinity): with entries of at most 1 the products below neither overflow nor underflow, for
/// matrices of any magnitude (1e-300 as 1e300), as Eigen's solvers scale theirs.
template <typename Mat>
double scale_to_unit(Mat& X) {
  double scale = 0.0;
  for (Eigen::Index j = 0; j < X.cols(); ++j) {
    for (Eigen::Index i = 0; i < X.rows(); ++i) scale = std::max(scale, std::abs(X(i, j)));  // NaN skipped
  }
  if (!(scale > 0.0) || !std::isfinite(scale)) return 1.0;
  X /= scale;
  return scale;
}

/// Columns p and q of X become c x_p - s x_q and s x_p + c x_q (X <- X J).
template <typename Mat>
void rotate_columns(Mat& X, Eigen::Index p, Eigen::Index q, double c, double s) {
  for (Eigen::Index k = 0; k < X.rows(); ++k) {
    const double xp = X(k, p), xq = X(k, q);
    X(k, p) = c * xp - s * xq;
    X(k, q) = s * xp + c * xq;
  }
}

/// Swaps columns i and j of X.
template <typename Mat>
void swap_columns(Mat& X, Eigen::Index i, Eigen::Index j) {
  for (Eigen::Index k = 0; k < X.rows(); ++k) std::swap(X(k, i), X(k, j));
}

/// Sorts `values` (ascending, or decreasing when `decreasing`), permuting the columns of each
/// matrix in `columns` alongside (a null pointer is skipped). Selection sort: at most 12 values.
template <typename Vec, typename Mat, std::size_t N>
void sort_with_columns(Vec& values, bool decreasing, Mat* const (&columns)[N]) {
  const Eigen::Index n = values.size();
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::Index best = i;
    for (Eigen::Index j = i + 1; j < n; ++j) {
      if (decreasing ? values(j) > values(best) : values(j) < values(best)) best = j;
    }
    if (best == i) continue;
    std::swap(values(i), values(best));
    for (Mat* X : columns) {
      if (X != nullptr) swap_columns(*X, i, best);
    }
  }
}

/// S = Q diag(mu) Q^T for a symmetric S given by its lower triangle (the upper one is not read),
/// mu ascending, by cyclic Jacobi rotations S <- J^T S J until every off-diagonal entry is
/// negligible: |s_pq| <= eps sqrt(|s_pp s_qq|). S is overwritten; Q is not touched unless
/// `vectors`. A NaN in S gives NaNs, never a hang.
template <typename Mat, typename Vec>
void symmetric_eigen(Mat& S, Vec& mu, Mat& Q, bool vectors) {
  const Eigen::Index n = S.rows();
  constexpr double eps = std::numeric_limits<double>::epsilon();
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index i = 0; i < j; ++i) S(i, j) = S(j, i);
  }
  const double scale = scale_to_unit(S);
  if (vectors) Q.setIdentity(n, n);
  for (int sweep = 0; sweep < kMaxJacobiSweeps; ++sweep) {
    bool rotated = false;
    for (Eigen::Index p = 0; p < n; ++p) {
      for (Eigen::Index q = p + 1; q < n; ++q) {
        const double apq = S(p, q);
        if (!(std::abs(apq) > eps * std::sqrt(std::abs(S(p, p) * S(q, q))))) continue;
        double c = 1.0, s = 0.0;
        jacobi_rotation(S(p, p), S(q, q), apq, c, s);
        rotate_columns(S, p, q, c, s);
        for (Eigen::Index k = 0; k < n; ++k) {  // rows p and q: S <- J^T S
          const double sp = S(p, k), sq = S(q, k);
          S(p, k) = c * sp - s * sq;
          S(q, k) = s * sp + c * sq;
        }
        S(p, q) = S(q, p) = 0.0;  // what the rotation was chosen to give
        if (vectors) rotate_columns(Q, p, q, c, s);
        rotated = true;
      }
    }
    if (!rotated) break;
  }
  mu = scale * S.diagonal();
  Mat* const eigenvectors[] = {vectors ? &Q : nullptr};
  sort_with_columns(mu, false, eigenvectors);
}

/// One-sided Jacobi (Hestenes): rotates the columns of W (and, alongside, of R, which starts as
/// the identity) until they are mutually orthogonal, W_final = W R with R orthogonal. A pair is
/// left alone when |w_p . w_q| <= eps |w_p| |w_q|, or when either column is below `negligible`
/// (numerically zero: such columns are not worth orthogonalising, their directions are noise).
template <typename Mat>
void orthogonalize_columns(Mat& W, Mat& R, double negligible) {
  const Eigen::Index k = W.cols();
  constexpr double eps = std::numeric_limits<double>::epsilon();
  R.setIdentity(k, k);
  const double floor2 = negligible * negligible;
  for (int sweep = 0; sweep < kMaxJacobiSweeps; ++sweep) {
    bool rotated = false;
    for (Eigen::Index p = 0; p < k; ++p) {
      for (Eigen::Index q = p + 1; q < k; ++q) {
        const double alpha = W.col(p).squaredNorm(), beta = W.col(q).squaredNorm();
        const double gamma = W.col(p).dot(W.col(q));
        if (!(alpha > floor2 && beta > floor2)) continue;
        if (!(std::abs(gamma) > eps * std::sqrt(alpha * beta))) continue;
        double c = 1.0, s = 0.0;  // diagonalises the Gram matrix [[alpha, gamma], [gamma, beta]]
        jacobi_rotation(alpha, beta, gamma, c, s);
        rotate_columns(W, p, q, c, s);
        rotate_columns(R, p, q, c, s);
        rotated = true;
      }
    }
    if (!rotated) break;
  }
}

/// Columns [valid, cols) of B become an orthonormal basis of the complement of its first `valid`
/// (orthonormal) columns: Gram-Schmidt, done twice, on the unit vector e_i that keeps most of
/// its length.
template <typename Mat>
void complete_orthonormal(Mat& B, Eigen::Index valid) {
  const Eigen::Index r = B.rows();
  for (Eigen::Index j = valid; j < B.cols(); ++j) {
    Eigen::VectorXd best = Eigen::VectorXd::Zero(r);
    double best_norm = -1.0;
    for (Eigen::Index i = 0; i < r; ++i) {
      Eigen::VectorXd v = Eigen::VectorXd::Unit(r, i);
      for (int pass = 0; pass < 2; ++pass) {
        for (Eigen::Index c = 0; c < j; ++c) v -= B.col(c).dot(v) * B.col(c);
      }
      if (v.norm() > best_norm) {
        best_norm = v.norm();
        best = v;
      }
    }
    B.col(j) = best / best_norm;
  }
}

}  // namespace opspace::detail
