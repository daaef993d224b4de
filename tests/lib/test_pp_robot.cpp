// The PP robot's closed forms (pp_robot.hpp) are the oracles of problem 1a's graded tests.
// Here they are checked against their own derivations: the kinetic energy for A, the
// definition x_ee = d1 + d2 for J, and the general formulas of linalg.hpp for the inverses.
#include <doctest/doctest.h>

#include "opspace/algorithms/linalg.hpp"
#include "opspace/algorithms/pp_robot.hpp"
#include "grader/suite/random.hpp"

namespace pp = opspace::pp;
using opspace::testing::Random;

constexpr double kTol = 1e-12;  // 2x2 closed forms: round-off only

TEST_CASE("the PP mass matrix reproduces the kinetic energy of both links") {
  // T = 1/2 m1 d1dot^2 + 1/2 m2 (d1dot + d2dot)^2 must equal 1/2 qdot^T A qdot.
  Random rng(21);
  for (int trial = 0; trial < 20; ++trial) {
    const double m1 = rng.uniform(0.5, 20.0), m2 = rng.uniform(0.5, 20.0);
    const Eigen::Vector2d qd(rng.uniform(-2, 2), rng.uniform(-2, 2));
    const double T = 0.5 * m1 * qd(0) * qd(0) + 0.5 * m2 * (qd(0) + qd(1)) * (qd(0) + qd(1));
    CHECK(0.5 * qd.dot(pp::mass_matrix(m1, m2) * qd) == doctest::Approx(T).epsilon(kTol));
  }
}

TEST_CASE("the PP task Jacobian maps joint rates to the end-effector rate") {
  // x_ee = d1 + d2, so a finite step in each joint moves x_ee by exactly that step.
  CHECK(pp::task_jacobian() == Eigen::RowVector2d(1.0, 1.0));
}

TEST_CASE("the PP closed-form inverses agree with the general formulas") {
  const Eigen::MatrixXd J = pp::task_jacobian();
  Random rng(22);
  SUBCASE("J+ and its projector") {
    CHECK((opspace::pseudo_inverse(J) - pp::pseudo_inverse()).norm() < kTol);
    CHECK((opspace::nullspace_projector(J, pp::pseudo_inverse()) - pp::pseudo_inverse_nullspace()).norm() < kTol);
  }
  SUBCASE("J# and its projector at random weights") {
    for (int trial = 0; trial < 10; ++trial) {
      const double w1 = rng.uniform(0.1, 10.0), w2 = rng.uniform(0.1, 10.0);
      const Eigen::MatrixXd W = Eigen::Vector2d(w1, w2).asDiagonal();
      CHECK((opspace::weighted_inverse(J, W) - pp::weighted_inverse(w1, w2)).norm() < kTol);
      CHECK((opspace::nullspace_projector(J, pp::weighted_inverse(w1, w2)) -
             pp::weighted_inverse_nullspace(w1, w2)).norm() < kTol);
    }
  }
  SUBCASE("Jbar and its projector at random masses") {
    for (int trial = 0; trial < 10; ++trial) {
      const Eigen::MatrixXd A = pp::mass_matrix(rng.uniform(0.5, 20.0), rng.uniform(0.5, 20.0));
      CHECK((opspace::dynamically_consistent_inverse(J, A) - pp::inertia_weighted_inverse()).norm() < kTol);
    }
    CHECK((opspace::nullspace_projector(J, pp::inertia_weighted_inverse()) - pp::inertia_weighted_nullspace()).norm() < kTol);
  }
}
