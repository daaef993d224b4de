// The operational-space matrices (opspace.hpp) against their definitions and the identities
// of Khatib's formulation, at random mass matrices and Jacobians, and near a singularity.
#include <doctest/doctest.h>

#include <Eigen/Dense>

#include "opspace/algorithms/linalg.hpp"
#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/algorithms/opspace.hpp"
#include "opspace/model/urdf.hpp"
#include "grader/suite/random.hpp"

using opspace::testing::Random;

namespace {

// Random A with eigenvalues in [0.1, ~7] and J with entries in [-1, 1]: Lambda^-1 has a
// condition number well under 1e4, so identities hold to ~1e-12; 1e-9 leaves a margin.
constexpr double kTol = 1e-9;

}  // namespace

TEST_CASE("Lambda, Jbar, N and p match their definitions for a full-rank task") {
  Random rng(31);
  // (6, 7), (3, 6) and (3, 3) run the kernels compiled for the problem set's shapes; the
  // others, up to the largest TaskSpace (6, 12), run the same code with run-time sizes.
  for (const auto& [m, n] : {std::pair<int, int>{3, 6}, {6, 7}, {3, 3}, {1, 2}, {2, 7}, {6, 12}}) {
    const Eigen::MatrixXd A = rng.spd(n);
    const Eigen::MatrixXd J = rng.matrix(m, n);
    const Eigen::VectorXd g = rng.vector(n);
    opspace::TaskSpace ts(m, n);
    opspace::operational_space(A, J, g, ts);
    CAPTURE(m);
    CAPTURE(n);
    const Eigen::MatrixXd Lambda = (J * A.inverse() * J.transpose()).inverse();  // plain inverses
    CHECK(ts.rank == m);
    CHECK((ts.Lambda - Lambda).norm() < kTol * Lambda.norm());
    CHECK((ts.Jbar - opspace::dynamically_consistent_inverse(J, A)).norm() < kTol);
    CHECK((ts.N - (Eigen::MatrixXd::Identity(n, n) - ts.Jbar * J)).norm() < kTol);
    CHECK((ts.p - ts.Jbar.transpose() * g).norm() < kTol);
  }
}

TEST_CASE("null-space torques N^T tau0 cause no task acceleration") {
  // xdd = J A^-1 tau (at rest, no gravity): the defining property of dynamic consistency.
  Random rng(32);
  const Eigen::MatrixXd A = rng.spd(7);
  const Eigen::MatrixXd J = rng.matrix(6, 7);
  opspace::TaskSpace ts(6, 7);
  opspace::operational_space(A, J, Eigen::VectorXd::Zero(7), ts);
  const Eigen::VectorXd tau0 = rng.vector(7, -50.0, 50.0);
  CHECK((J * A.inverse() * ts.N.transpose() * tau0).norm() < kTol * tau0.norm());
}

TEST_CASE("a task force F = Lambda xdd_d produces exactly xdd_d") {
  // tau = J^T Lambda a  =>  xdd = J A^-1 J^T Lambda a = a (no gravity, at rest)
  Random rng(33);
  const Eigen::MatrixXd A = rng.spd(6);
  const Eigen::MatrixXd J = rng.matrix(3, 6);
  opspace::TaskSpace ts(3, 6);
  opspace::operational_space(A, J, Eigen::VectorXd::Zero(6), ts);
  const Eigen::VectorXd a = rng.vector(3);
  CHECK((J * A.inverse() * J.transpose() * ts.Lambda * a - a).norm() < kTol);
}

TEST_CASE("near a singularity Lambda stays finite and drops only the singular direction") {
  // Two task rows that differ by eps: J A^-1 J^T has one eigenvalue of order eps^2.
  Random rng(34);
  const Eigen::MatrixXd A = rng.spd(6);
  Eigen::MatrixXd J = rng.matrix(3, 6);
  opspace::TaskSpace ts(3, 6);
  SUBCASE("exactly singular: rank 2, finite, still dynamically consistent") {
    J.row(2) = J.row(1);
    opspace::operational_space(A, J, rng.vector(6), ts);
    CHECK(ts.rank == 2);
    CHECK(ts.Lambda.allFinite());
    CHECK(ts.Jbar.allFinite());
    CHECK(ts.N.allFinite());
    CHECK(ts.p.allFinite());
    // The kept directions are still decoupled from the null space.
    CHECK((J * A.inverse() * ts.N.transpose()).norm() < 1e-8);
  }
  SUBCASE("within the tolerance of a singularity (eps^2 = 1e-10 < 1e-6): the direction is dropped") {
    J.row(2) = J.row(1) + 1e-5 * rng.matrix(1, 6);
    opspace::operational_space(A, J, rng.vector(6), ts);
    CHECK(ts.rank == 2);
    CHECK(ts.Lambda.norm() < 1e3);  // no 1/eps^2 blow-up
  }
  SUBCASE("well outside the tolerance (eps^2 = 1e-2 > 1e-6): all directions are kept") {
    J.row(2) = J.row(1) + 1e-1 * rng.matrix(1, 6);
    opspace::operational_space(A, J, rng.vector(6), ts);
    CHECK(ts.rank == 3);
  }
}

TEST_CASE("a task space beyond the fixed maximum sizes is refused with the sizes named") {
  CHECK_THROWS_WITH_AS(opspace::TaskSpace(7, 7), doctest::Contains("the task dimension is 7, expected 1 to 6"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(opspace::TaskSpace(3, 13), doctest::Contains("the number of joints is 13, expected 1 to 12"),
                       std::invalid_argument);
}

TEST_CASE("operational_space names the mismatch in its error") {
  opspace::TaskSpace ts(3, 6);
  Random rng(35);
  CHECK_THROWS_WITH_AS(opspace::operational_space(rng.spd(6), rng.matrix(3, 7), rng.vector(6), ts),
                       doctest::Contains("J is 3x7, expected 3x6"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(opspace::operational_space(-Eigen::MatrixXd::Identity(6, 6), rng.matrix(3, 6),
                                                  rng.vector(6), ts),
                       doctest::Contains("not positive definite"), std::invalid_argument);
}

TEST_CASE("at the 3R arm's stretched-up singularity Lambda keeps only the one direction left") {
  // robots/rrr.urdf at theta = (0, 90 deg, 0) points straight up (problem 4): joint 1 turns
  // the tip about its own axis and joints 2, 3 both move it along X0, so Jv has rank 1.
  const opspace::Model model = opspace::load_urdf(opspace::robot_path("rrr.urdf"));
  opspace::Data data(model);
  const int tip = model.frame_id("end-effector");
  opspace::Matrix6Xd J0(6, 3);
  opspace::TaskSpace ts(3, 3);
  auto task_space_at = [&](const Eigen::Vector3d& q) {
    opspace::forward_kinematics(model, data, q);
    opspace::point_jacobian(model, data, tip, Eigen::Vector3d::Zero(), J0);
    const Eigen::MatrixXd Jv = J0.topRows<3>();
    opspace::operational_space(opspace::crba(model, data, q), Jv, opspace::generalized_gravity(model, data, q), ts);
    return Jv;
  };
  const double half_pi = std::acos(0.0);

  SUBCASE("exactly at the singularity: rank 1, everything finite, the null space still decoupled") {
    const Eigen::MatrixXd Jv = task_space_at(Eigen::Vector3d(0.0, half_pi, 0.0));
    CHECK(ts.rank == 1);
    CHECK(ts.Lambda.allFinite());
    CHECK(ts.N.allFinite());
    CHECK(ts.p.allFinite());
    // The one task direction kept is X0: Lambda has no component along Y0 or Z0.
    CHECK(ts.Lambda.row(1).norm() < 1e-9);
    CHECK(ts.Lambda.row(2).norm() < 1e-9);
    const Eigen::MatrixXd A = opspace::crba(model, data, Eigen::Vector3d(0.0, half_pi, 0.0));
    CHECK((Jv * A.inverse() * ts.N.transpose()).norm() < 1e-9);
  }
  SUBCASE("close to the singularity: Lambda stays within the bound the cut-off guarantees") {
    // Off by eps, the two vanishing singular values of Jv are O(eps) (the elbow shortens the
    // reach by L3 eps per radian, joint 1 swings a tip that is ~L2 eps off its axis), so
    // J A^-1 J^T has eigenvalues O(eps^2). Dropping mu_i <= tol mu_max bounds every eigenvalue
    // of Lambda by 1 / (tol mu_max); without the cut-off eps = 1e-5 would give ~1e10.
    for (const double eps : {1e-2, 1e-3, 1e-5, 1e-7}) {
      CAPTURE(eps);
      task_space_at(Eigen::Vector3d(0.0, half_pi - eps, eps));
      const double mu_max = ts.Lambda_inv.selfadjointView<Eigen::Lower>().eigenvalues().maxCoeff();
      const double lambda_max = ts.Lambda.selfadjointView<Eigen::Lower>().eigenvalues().maxCoeff();
      CHECK(ts.Lambda.allFinite());
      CHECK(lambda_max <= (1.0 + 1e-9) / (opspace::kTaskInertiaTolerance * mu_max));
    }
  }
}
