/// @file random.hpp
/// Seeded random matrices for tests: the same numbers on every run and every machine.
#pragma once

#include <Eigen/Core>
#include <random>

namespace opspace::testing {

class Random {
 public:
  explicit Random(unsigned seed) : engine_(seed) {}

  /// Uniform number in [lo, hi).
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }

  /// rows x cols matrix with entries uniform in [-1, 1).
  Eigen::MatrixXd matrix(Eigen::Index rows, Eigen::Index cols) {
    Eigen::MatrixXd M(rows, cols);
    for (Eigen::Index i = 0; i < M.size(); ++i) M(i) = uniform(-1.0, 1.0);
    return M;
  }

  Eigen::VectorXd vector(Eigen::Index n, double lo = -1.0, double hi = 1.0) {
    Eigen::VectorXd v(n);
    for (Eigen::Index i = 0; i < n; ++i) v(i) = uniform(lo, hi);
    return v;
  }

  /// Symmetric positive definite n x n matrix, eigenvalues >= min_eigenvalue:
  /// B B^T is positive semi-definite, adding min_eigenvalue * I makes it definite.
  Eigen::MatrixXd spd(Eigen::Index n, double min_eigenvalue = 0.1) {
    const Eigen::MatrixXd B = matrix(n, n);
    return B.lazyProduct(B.transpose()) + min_eigenvalue * Eigen::MatrixXd::Identity(n, n);
  }

  std::mt19937& engine() { return engine_; }

 private:
  std::mt19937 engine_;
};

}  // namespace opspace::testing
