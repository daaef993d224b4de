// Generalized inverses and projectors (linalg.hpp), checked against the identities that
// define them: the four Penrose conditions, J J_inv = I for a right inverse, the closed
// form of the weighted inverse, and the properties of a projector.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "opspace/algorithms/linalg.hpp"
#include "grader/suite/random.hpp"

using opspace::testing::Random;

namespace {

// Shapes of the course: PP task (1x2), PUMA position task (3x6), iiwa full task (6x7), a
// square arm (3x3) and a tall matrix (7x3) for the pseudo-inverse's other side.
const std::pair<int, int> kShapes[] = {{1, 2}, {3, 6}, {6, 7}, {3, 3}, {7, 3}};

// Round-off of an SVD of a well-conditioned random matrix is ~1e-15 times its norm; the
// random matrices here have condition numbers well under 1e3, so 1e-10 leaves a margin.
constexpr double kTol = 1e-10;

std::string shape_name(const Eigen::MatrixXd& M) {
  return std::to_string(M.rows()) + "x" + std::to_string(M.cols());
}

}  // namespace

TEST_CASE("the pseudo-inverse satisfies the four Penrose conditions") {
  Random rng(11);
  for (const auto& [m, n] : kShapes) {
    for (int trial = 0; trial < 5; ++trial) {
      const Eigen::MatrixXd J = rng.matrix(m, n);
      const Eigen::MatrixXd P = opspace::pseudo_inverse(J);
      CAPTURE(shape_name(J));
      REQUIRE(P.rows() == n);
      REQUIRE(P.cols() == m);
      CHECK((J * P * J - J).norm() < kTol);                            // J J+ J = J
      CHECK((P * J * P - P).norm() < kTol);                            // J+ J J+ = J+
      CHECK(((J * P).transpose() - J * P).norm() < kTol);              // (J J+)^T = J J+
      CHECK(((P * J).transpose() - P * J).norm() < kTol);              // (J+ J)^T = J+ J
    }
  }
}

TEST_CASE("a full-row-rank Jacobian has J J_inv = I for every right inverse") {
  Random rng(12);
  for (const auto& [m, n] : kShapes) {
    if (m > n) continue;  // a tall matrix has no right inverse
    const Eigen::MatrixXd J = rng.matrix(m, n);
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(m, m);
    CAPTURE(shape_name(J));
    SUBCASE("pseudo-inverse") { CHECK((J * opspace::pseudo_inverse(J) - I).norm() < kTol); }
    SUBCASE("weighted inverse") { CHECK((J * opspace::weighted_inverse(J, rng.spd(n)) - I).norm() < kTol); }
    SUBCASE("dynamically consistent inverse") {
      CHECK((J * opspace::dynamically_consistent_inverse(J, rng.spd(n)) - I).norm() < kTol);
    }
  }
}

TEST_CASE("the pseudo-inverse of a full-row-rank J equals J^T (J J^T)^-1") {
  // The closed form of problem 1a(iv), evaluated with a plain LU inverse.
  Random rng(13);
  for (const auto& [m, n] : kShapes) {
    if (m > n) continue;
    const Eigen::MatrixXd J = rng.matrix(m, n);
    const Eigen::MatrixXd closed_form = J.transpose() * (J * J.transpose()).inverse();
    CAPTURE(shape_name(J));
    CHECK((opspace::pseudo_inverse(J) - closed_form).norm() < kTol);
  }
}

TEST_CASE("the weighted inverse equals W^-1 J^T (J W^-1 J^T)^-1") {
  Random rng(14);
  SUBCASE("random SPD weights, closed form with plain inverses") {
    for (const auto& [m, n] : kShapes) {
      if (m > n) continue;
      const Eigen::MatrixXd J = rng.matrix(m, n);
      const Eigen::MatrixXd W = rng.spd(n);
      const Eigen::MatrixXd Winv = W.inverse();
      const Eigen::MatrixXd closed_form = Winv * J.transpose() * (J * Winv * J.transpose()).inverse();
      CAPTURE(shape_name(J));
      CHECK((opspace::weighted_inverse(J, W) - closed_form).norm() < kTol);
    }
  }
  SUBCASE("the identity weight gives the pseudo-inverse") {
    const Eigen::MatrixXd J = rng.matrix(3, 6);
    CHECK((opspace::weighted_inverse(J, Eigen::MatrixXd::Identity(6, 6)) - opspace::pseudo_inverse(J)).norm() < kTol);
  }
  SUBCASE("W = diag(w1, w2) on J = [1 1] gives [w2, w1] / (w1 + w2) (problem 1a(v))") {
    const double w1 = 3.0, w2 = 7.0;
    const Eigen::MatrixXd J = Eigen::RowVector2d(1.0, 1.0);
    const Eigen::Vector2d expected(w2 / (w1 + w2), w1 / (w1 + w2));
    CHECK((opspace::weighted_inverse(J, Eigen::Vector2d(w1, w2).asDiagonal().toDenseMatrix()) - expected).norm() < kTol);
  }
}

TEST_CASE("the dynamically consistent inverse makes the null space A-orthogonal to the task") {
  // Jbar's defining property: J A^-1 N^T = 0, so torques N^T tau0 cause no task acceleration.
  Random rng(15);
  const Eigen::MatrixXd J = rng.matrix(3, 6);
  const Eigen::MatrixXd A = rng.spd(6);
  const Eigen::MatrixXd N = opspace::nullspace_projector(J, opspace::dynamically_consistent_inverse(J, A));
  CHECK((J * A.inverse() * N.transpose()).norm() < kTol);
}

TEST_CASE("a null-space projector is idempotent and annihilates the task") {
  Random rng(16);
  for (const auto& [m, n] : kShapes) {
    if (m > n) continue;
    const Eigen::MatrixXd J = rng.matrix(m, n);
    const Eigen::MatrixXd N = opspace::nullspace_projector(J, opspace::weighted_inverse(J, rng.spd(n)));
    CAPTURE(shape_name(J));
    CHECK((N * N - N).norm() < kTol);  // a projector: N^2 = N
    CHECK((J * N).norm() < kTol);      // joint motion N dq0 leaves the task still
  }
}

TEST_CASE("a rank-deficient Jacobian gives finite inverses, never inf or NaN") {
  // Two identical rows: rank 1 of 2. Behaviour documented in linalg.hpp: the zero singular
  // value is dropped, so J J_inv is the projector onto range(J) = span([1, 1]^T).
  Eigen::MatrixXd J(2, 3);
  J << 1.0, 2.0, 3.0, 1.0, 2.0, 3.0;
  const Eigen::Matrix2d range_projector = 0.5 * Eigen::Matrix2d::Ones();
  Random rng(17);
  SUBCASE("pseudo-inverse") {
    const Eigen::MatrixXd P = opspace::pseudo_inverse(J);
    CHECK(P.allFinite());
    CHECK((J * P - range_projector).norm() < kTol);
  }
  SUBCASE("weighted inverse") {
    const Eigen::MatrixXd P = opspace::weighted_inverse(J, rng.spd(3));
    CHECK(P.allFinite());
    CHECK((J * P - range_projector).norm() < kTol);
  }
  SUBCASE("a zero Jacobian") {
    CHECK(opspace::pseudo_inverse(Eigen::MatrixXd::Zero(3, 6)).isZero());
    CHECK(opspace::weighted_inverse(Eigen::MatrixXd::Zero(3, 6), rng.spd(6)).isZero());
  }
}

TEST_CASE("bad input throws an error that names the problem") {
  Random rng(18);
  const Eigen::MatrixXd J = rng.matrix(3, 6);
  SUBCASE("a weight of the wrong size names both sizes") {
    CHECK_THROWS_WITH_AS(opspace::weighted_inverse(J, rng.spd(5)),
                         doctest::Contains("W (J is 3x6) is 5x5, expected 6x6"), std::invalid_argument);
  }
  SUBCASE("a non-symmetric weight") {
    Eigen::MatrixXd W = rng.spd(6);
    W(0, 1) += 0.5;
    CHECK_THROWS_WITH_AS(opspace::weighted_inverse(J, W), doctest::Contains("not symmetric"),
                         std::invalid_argument);
  }
  SUBCASE("an indefinite weight") {
    Eigen::MatrixXd W = Eigen::MatrixXd::Identity(6, 6);
    W(2, 2) = -1.0;
    CHECK_THROWS_WITH_AS(opspace::weighted_inverse(J, W), doctest::Contains("not positive definite"),
                         std::invalid_argument);
  }
  SUBCASE("a projector from an inverse of the wrong shape") {
    CHECK_THROWS_WITH_AS(opspace::nullspace_projector(J, rng.matrix(3, 6)),
                         doctest::Contains("J_inv (J is 3x6) is 3x6, expected 6x3"), std::invalid_argument);
  }
  SUBCASE("NaN in J") {
    Eigen::MatrixXd bad = J;
    bad(1, 1) = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH_AS(opspace::pseudo_inverse(bad), doctest::Contains("NaN"), std::invalid_argument);
  }
}

// opspace::svd is the library's own one-sided Jacobi SVD (linalg.cpp): checked against Eigen's
// JacobiSVD, an independent implementation, and against the definition U diag(sigma) V^T = M
// with orthonormal U and V. Both are backward stable, so their singular values agree to a few
// eps * sigma_max (1e-13 leaves a margin of ~100 over the worst of 20000 random cases).
TEST_CASE("opspace::svd agrees with Eigen's JacobiSVD on every shape up to 7x7, rank-deficient ones too") {
  Random rng(19);
  constexpr double kAgree = 1e-13;
  for (int rows = 1; rows <= 7; ++rows) {
    for (int cols = 1; cols <= 7; ++cols) {
      for (int variant = 0; variant < 3; ++variant) {
        Eigen::MatrixXd M = rng.matrix(rows, cols);
        if (variant == 1 && rows > 1) M.row(rows - 1) = 0.5 * M.row(0);  // a repeated row
        if (variant == 2 && cols > 1) M.col(cols - 1) = -2.0 * M.col(0);  // a repeated column
        const std::string what = shape_name(M) + " variant " + std::to_string(variant);
        const Eigen::JacobiSVD<Eigen::MatrixXd> eigen_svd(M);
        const opspace::Svd full = opspace::svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
        const double sigma_max = eigen_svd.singularValues()(0);
        CHECK_MESSAGE((full.sigma - eigen_svd.singularValues()).cwiseAbs().maxCoeff() < kAgree * sigma_max,
                      what << ": singular values differ from Eigen's");
        const int k = std::min(rows, cols);
        Eigen::MatrixXd S = Eigen::MatrixXd::Zero(rows, cols);
        S.diagonal() = full.sigma;
        CHECK_MESSAGE((full.U * S * full.V.transpose() - M).norm() < kAgree * sigma_max,
                      what << ": U diag(sigma) V^T is not M");
        CHECK_MESSAGE((full.U.transpose() * full.U - Eigen::MatrixXd::Identity(rows, rows)).norm() < kAgree,
                      what << ": full U is not orthonormal (a completed column?)");
        CHECK_MESSAGE((full.V.transpose() * full.V - Eigen::MatrixXd::Identity(cols, cols)).norm() < kAgree,
                      what << ": full V is not orthonormal (a completed column?)");
        const opspace::Svd thin = opspace::svd(M, Eigen::ComputeThinU | Eigen::ComputeThinV);
        CHECK_MESSAGE((thin.U.cols() == k && thin.V.cols() == k && thin.U.rows() == rows && thin.V.rows() == cols),
                      what << ": thin U is " << shape_name(thin.U) << ", thin V " << shape_name(thin.V));
        CHECK((thin.U * thin.sigma.asDiagonal() * thin.V.transpose() - M).norm() < kAgree * sigma_max);
        const opspace::Svd values = opspace::svd(M, 0);
        CHECK_MESSAGE((values.U.size() == 0 && values.V.size() == 0), what << ": U or V computed unasked");
      }
    }
  }
}

TEST_CASE("the singular vectors of a zero matrix still form orthonormal bases") {
  // Every sigma is 0: no column of M V gives a direction, all of U and V come from completion.
  const opspace::Svd d = opspace::svd(Eigen::MatrixXd::Zero(3, 5), Eigen::ComputeFullU | Eigen::ComputeFullV);
  CHECK(d.sigma.isZero(0.0));
  CHECK((d.U.transpose() * d.U - Eigen::Matrix3d::Identity()).norm() < 1e-15);
  CHECK((d.V.transpose() * d.V - Eigen::MatrixXd::Identity(5, 5)).norm() < 1e-15);
}

TEST_CASE("the symmetric pseudo-inverse agrees with Eigen's SelfAdjointEigenSolver, rank-deficient too") {
  // M+ = Q D+ Q^T from the library's Jacobi eigen-decomposition against the same formula with
  // Eigen's solver (an independent implementation). A perturbation dM of M moves M+ by about
  // |M+|^2 |dM|, so two backward-stable results differ by ~eps cond |M+| (cond over the kept
  // eigenvalues); the bound allows 1000 times that.
  Random rng(20);
  for (int n = 1; n <= 7; ++n) {
    for (int rank = 1; rank <= n; ++rank) {
      const Eigen::MatrixXd B = rng.matrix(n, rank);
      const Eigen::MatrixXd M = B * B.transpose();
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(M);
      Eigen::VectorXd d_inv = Eigen::VectorXd::Zero(n);
      const double cutoff = opspace::kSvdTolerance * eig.eigenvalues()(n - 1);
      for (int i = 0; i < n; ++i) d_inv(i) = eig.eigenvalues()(i) > cutoff ? 1.0 / eig.eigenvalues()(i) : 0.0;
      const double cond = eig.eigenvalues()(n - 1) * d_inv.maxCoeff();
      const double bound = 1e3 * std::numeric_limits<double>::epsilon() * cond;
      const Eigen::MatrixXd expected = eig.eigenvectors() * d_inv.asDiagonal() * eig.eigenvectors().transpose();
      const Eigen::MatrixXd got = opspace::symmetric_pseudo_inverse(M);
      CHECK_MESSAGE((got - expected).norm() < bound * expected.norm(),
                    n << "x" << n << " of rank " << rank << " (cond " << cond << "): M+ differs from Eigen's");
    }
  }
}

TEST_CASE("the SVD and the symmetric pseudo-inverse work at any magnitude, 1e-300 as 1e300") {
  // Both are homogeneous: svd(c M).sigma = c svd(M).sigma and (c S)+ = S+ / c. Unscaled, the
  // products inside the Jacobi rotations overflow at 1e300 and underflow at 1e-300.
  Random rng(21);
  const Eigen::MatrixXd M = rng.matrix(3, 7);
  const Eigen::MatrixXd S = rng.spd(4);
  const Eigen::VectorXd sigma = opspace::svd(M, 0).sigma;
  const Eigen::MatrixXd S_inv = opspace::symmetric_pseudo_inverse(S);
  for (const double c : {1e-300, 1e300}) {
    CAPTURE(c);
    const opspace::Svd d = opspace::svd(c * M, Eigen::ComputeFullU | Eigen::ComputeFullV);
    CHECK((d.sigma / c - sigma).norm() < 1e-14 * sigma(0));
    CHECK((d.V.transpose() * d.V - Eigen::MatrixXd::Identity(7, 7)).norm() < 1e-14);
    CHECK((opspace::symmetric_pseudo_inverse(c * S) * c - S_inv).norm() < 1e-12 * S_inv.norm());
  }
}
