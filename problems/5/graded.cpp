// Graded test of problem 5: the task inertia at random full-rank Jacobians and random mass
// matrices, against its definition Lambda (J A^-1 J^T) = I (an identity the answer must satisfy,
// whatever way it is computed) and against the oracle's Cholesky solve.
#include <cmath>

#include "answers.hpp"
#include "suite.hpp"
#include "support/random.hpp"

namespace opspace::grading {

namespace {

using testing::Random;

// 2x2 products of well-conditioned matrices: round-off ~1e-14; 1e-9 accepts any correct way.
constexpr double kTol = 1e-9;
constexpr int kTrials = 5;

void task_inertia(const Hw2Api& api, Check& check) {
  Random rng(seed_for(501));
  for (int trial = 0; trial < kTrials; ++trial) {
    // Rows of J at least 60 degrees apart and of length 0.5-2: full rank, well conditioned.
    const double a = rng.uniform(0.0, 6.28), b = a + rng.uniform(1.05, 2.09);
    Eigen::Matrix2d J;
    J << rng.uniform(0.5, 2.0) * Eigen::RowVector2d(std::cos(a), std::sin(a)),
        rng.uniform(0.5, 2.0) * Eigen::RowVector2d(std::cos(b), std::sin(b));
    const Eigen::Matrix2d W = rng.spd(2, 0.5);
    const Eigen::Matrix2d A = 0.5 * (W + W.transpose());
    const Eigen::Matrix2d Lambda = api.p5.task_inertia(J, A);
    if (!check.near("Lambda (J A^-1 J^T) for J = " + format(J) + ", A = " + format(A), Eigen::Matrix2d::Identity(),
                    Eigen::Matrix2d(Lambda * J * A.llt().solve(J.transpose())), kTol,
                    "Lambda is the inverse of J A^-1 J^T, the inertia the tip shows to a force"))
      return;
    if (!check.near("Lambda for J = " + format(J) + ", A = " + format(A), oracle::answer::p5::task_inertia(J, A), Lambda,
                    kTol, "Lambda = (J A^-1 J^T)^-1"))
      return;
  }
}

}  // namespace

Problem problem_5() {
  return {"5",
          "2R planar arm: the task inertia of its tip",
          {
              {"i. the task inertia is (J A^-1 J^T)^-1 at random Jacobians and mass matrices", 3,
               "Invert the operational-space mobility J A^-1 J^T.", task_inertia},
          }};
}

}  // namespace opspace::grading
