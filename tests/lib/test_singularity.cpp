// The singularity analysis (singularity.hpp): position Hessians against finite differences of
// the Jacobian, the SVD split against Jacobians of known singular values, and the 3R arm's
// singular pose against the problem set's answers and closed forms.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "opspace/algorithms/kinematics.hpp"
#include "opspace/algorithms/singularity.hpp"
#include "opspace/math/constants.hpp"
#include "opspace/model/urdf.hpp"
#include "grader/suite/random.hpp"

using opspace::SingularityType;
using opspace::testing::Random;

namespace {

using opspace::kPi;

Eigen::MatrixXd jv_at(const opspace::Model& model, const Eigen::VectorXd& q, int frame, const Eigen::Vector3d& p) {
  opspace::Data data(model);
  opspace::forward_kinematics(model, data, q);
  opspace::Matrix6Xd J0(6, model.dof());
  opspace::point_jacobian(model, data, frame, p, J0);
  return J0.topRows<3>();
}

// An orthogonal 3x3 matrix from a random one (Q of its QR factorization).
Eigen::Matrix3d random_rotation(Random& rng) {
  return Eigen::HouseholderQR<Eigen::Matrix3d>(Eigen::Matrix3d(rng.matrix(3, 3))).householderQ();
}

}  // namespace

TEST_CASE("the position Hessian is the derivative of Jv, by central differences") {
  Random rng(71);
  for (const char* file : {"rrr.urdf", "puma.urdf", "iiwa7.urdf"}) {
    const opspace::Model model = opspace::load_urdf(opspace::robot_path(file));
    const int n = model.dof();
    const int frame = model.frame_id(model.frames.back().name);
    const Eigen::Vector3d p(0.03, -0.02, 0.05);  // a point off the frame origin
    for (int trial = 0; trial < 3; ++trial) {
      const Eigen::VectorXd q = rng.vector(n, -2.0, 2.0);
      opspace::Data data(model);
      opspace::forward_kinematics(model, data, q);
      Eigen::MatrixXd H(3 * n, n);
      opspace::point_position_hessian(model, data, frame, p, H);
      // d Jv(:, i) / dq_j ~ (Jv(q + h e_j) - Jv(q - h e_j)) / 2h: truncation ~h^2 (1e-10 with
      // h = 1e-5 and third derivatives of order 1 m), round-off ~1e-16 / h = 1e-11; 1e-7 is safe.
      const double h = 1e-5;
      for (int j = 0; j < n; ++j) {
        Eigen::VectorXd qp = q, qm = q;
        qp(j) += h;
        qm(j) -= h;
        const Eigen::MatrixXd dJ = (jv_at(model, qp, frame, p) - jv_at(model, qm, frame, p)) / (2 * h);
        for (int k = 0; k < 3; ++k) {
          CAPTURE(file);
          CAPTURE(j);
          CAPTURE(k);
          CHECK((H.middleRows(k * n, n).col(j).transpose() - dJ.row(k)).cwiseAbs().maxCoeff() < 1e-7);
        }
      }
      // A Hessian is symmetric: d^2 x / dq_i dq_j = d^2 x / dq_j dq_i.
      for (int k = 0; k < 3; ++k) {
        const Eigen::MatrixXd Hk = H.middleRows(k * n, n);
        CHECK((Hk - Hk.transpose()).cwiseAbs().maxCoeff() == 0.0);
      }
    }
  }
}

TEST_CASE("directions splits space at singular values above tol times the largest") {
  Random rng(72);
  const Eigen::Matrix3d U = random_rotation(rng);
  const Eigen::MatrixXd V = Eigen::HouseholderQR<Eigen::MatrixXd>(rng.matrix(5, 5)).householderQ();
  for (const auto& [small, rank] : {std::pair<double, int>{1e-3, 3}, {1e-9, 2}, {0.0, 2}}) {
    // J = U diag(2, 1, small) V^T (3 x 5): small = 1e-3 is 5e-4 of sigma_max, kept; 1e-9 is
    // below 1e-6 * 2, dropped.
    Eigen::Matrix<double, 3, 5> S = Eigen::Matrix<double, 3, 5>::Zero();
    S.diagonal() << 2.0, 1.0, small;
    const Eigen::Matrix<double, 3, 5> J = U * S * V.transpose();
    const opspace::Directions3 d = opspace::directions(J);
    CAPTURE(small);
    CHECK(d.rank == rank);
    CHECK(d.sigma(0) == doctest::Approx(2.0));
    // The singular subspace is spanned by the columns of U beyond the rank (up to sign).
    const Eigen::Matrix3d P = d.singular() * d.singular().transpose();
    const Eigen::Matrix3d P_expected = U.rightCols(3 - rank) * U.rightCols(3 - rank).transpose();
    CHECK((P - P_expected).norm() < 1e-9);
    // moving() and singular() together are an orthonormal basis.
    CHECK((d.moving() * d.moving().transpose() + P - Eigen::Matrix3d::Identity()).norm() < 1e-12);
  }
}

TEST_CASE("at theta = (0, 90 deg, 0) only X0 moves, Z0 is a Type I and Y0 a Type II singularity") {
  const opspace::Model rrr = opspace::load_urdf(opspace::robot_path("rrr.urdf"));
  opspace::Data data(rrr);
  const int tip = rrr.frame_id("end-effector");
  const Eigen::Vector3d q(0.0, kPi / 2, 0.0);
  const opspace::SingularityAnalysis a = opspace::analyse_singularities(rrr, data, tip, Eigen::Vector3d::Zero(), q);
  // Problem set, questions i-iv: one linear degree of freedom (X0); singular Z0 (Type I, listed
  // first) and Y0 (Type II); rotations about Y0 and Z0 (Jw's columns Z0, -Y0, -Y0).
  CHECK(a.linear.rank == 1);
  CHECK(std::abs(a.linear.U.col(0).dot(Eigen::Vector3d::UnitX())) == doctest::Approx(1.0));
  CHECK(a.type_one == 1);
  CHECK(a.type(0) == SingularityType::kTypeI);
  CHECK(a.type(1) == SingularityType::kTypeII);
  CHECK(std::abs(a.linear.U.col(1).dot(Eigen::Vector3d::UnitZ())) == doctest::Approx(1.0));
  CHECK(std::abs(a.linear.U.col(2).dot(Eigen::Vector3d::UnitY())) == doctest::Approx(1.0));
  CHECK(a.angular.rank == 2);
  CHECK(std::abs(a.angular.U.col(2).dot(Eigen::Vector3d::UnitX())) == doctest::Approx(1.0));
  // Jv = [0 -1 -0.5; 0 0 0; 0 0 0] (links 0.5 m): sigma_max = sqrt(1 + 0.25).
  CHECK(a.linear.sigma(0) == doctest::Approx(std::sqrt(1.25)));
}

TEST_CASE("the self-motion curvature along Z0 is the closed form of folding the elbow") {
  const opspace::Model rrr = opspace::load_urdf(opspace::robot_path("rrr.urdf"));
  opspace::Data data(rrr);
  const int tip = rrr.frame_id("end-effector");
  const Eigen::Vector3d q(0.0, kPi / 2, 0.0);
  opspace::forward_kinematics(rrr, data, q);
  opspace::Matrix6Xd J0(6, 3);
  opspace::point_jacobian(rrr, data, tip, Eigen::Vector3d::Zero(), J0);
  Eigen::MatrixXd H(9, 3);
  opspace::point_position_hessian(rrr, data, tip, Eigen::Vector3d::Zero(), H);
  const Eigen::Matrix<double, 3, 3> Jv = J0.topRows<3>();
  // Self-motions: joint 1, and the fold dq = (0, 1, -2) / sqrt(5) (-dq2 - 0.5 dq3 = 0). With
  // z = 0.35 + 0.5 sin q2 + 0.5 sin(q2 + q3), the fold gives z'' = -0.5 (1/5) - 0.5 (1/5) = -0.2;
  // joint 1 changes no height. So ||C_Z0||_2 = 0.2.
  CHECK(opspace::self_motion_curvature(Jv, H, Eigen::Vector3d::UnitZ()) == doctest::Approx(0.2));
  // With y = r sin q1, the only second derivatives are 2 (dr/dq) dq1 = 2 (-dq2 - 0.5 dq3) dq1 = 0
  // on the self-motions: round-off.
  CHECK(opspace::self_motion_curvature(Jv, H, Eigen::Vector3d::UnitY()) < 1e-12);
  CHECK(opspace::singularity_type(Jv, H, Eigen::Vector3d::UnitZ()) == SingularityType::kTypeI);
  CHECK(opspace::singularity_type(Jv, H, -Eigen::Vector3d::UnitY()) == SingularityType::kTypeII);
  CHECK(opspace::singularity_type(Jv, H, Eigen::Vector3d::UnitX()) == SingularityType::kNone);
  // A mixture of Z0 and Y0 is still singular, and Type I (C is linear in u).
  CHECK(opspace::singularity_type(Jv, H, Eigen::Vector3d(0, 1, 1).normalized()) == SingularityType::kTypeI);
}

TEST_CASE("the type split does not depend on the basis the SVD returns for the singular subspace") {
  const opspace::Model rrr = opspace::load_urdf(opspace::robot_path("rrr.urdf"));
  opspace::Data data(rrr);
  const int tip = rrr.frame_id("end-effector");
  Random rng(73);
  for (int trial = 0; trial < 5; ++trial) {
    // The straight-up arm turned about Z0 by q1: singular Z0 (Type I) and the plane's normal
    // n = (-sin q1, cos q1, 0) (Type II), whatever q1.
    const double q1 = rng.uniform(-kPi, kPi);
    const opspace::SingularityAnalysis a = opspace::analyse_singularities(
        rrr, data, tip, Eigen::Vector3d::Zero(), Eigen::Vector3d(q1, kPi / 2, 0.0));
    REQUIRE(a.linear.rank == 1);
    REQUIRE(a.type_one == 1);
    CHECK(std::abs(a.linear.U.col(1).z()) == doctest::Approx(1.0));
    CHECK(std::abs(a.linear.U.col(2).dot(Eigen::Vector3d(-std::sin(q1), std::cos(q1), 0.0))) ==
          doctest::Approx(1.0));
  }
}

TEST_CASE("a point without self-motions has only Type II singular directions") {
  // One joint moving the point along X0: Y0 and Z0 are singular, nothing moves without
  // moving the point, so no singular direction can be Type I.
  const Eigen::Matrix<double, 3, 1> Jv(1.0, 0.0, 0.0);
  const Eigen::Matrix<double, 3, 1> Jw(0.0, 0.0, 1.0);
  const Eigen::Vector3d H(0.0, 1.0, 0.0);  // stacked 1x1 Hessians: y'' = dq^2
  const opspace::SingularityAnalysis a = opspace::analyse_singularities(Jv, Jw, H);
  CHECK(a.linear.rank == 1);
  CHECK(a.type_one == 0);
  CHECK(opspace::singularity_type(Jv, H, Eigen::Vector3d::UnitY()) == SingularityType::kTypeII);
}

TEST_CASE("the analysis rejects NaN and Hessians of the wrong size") {
  Eigen::Matrix3d J = Eigen::Matrix3d::Identity();
  const Eigen::MatrixXd H = Eigen::MatrixXd::Zero(9, 3);
  CHECK_THROWS_AS(opspace::analyse_singularities(J, J, Eigen::MatrixXd::Zero(6, 3)), std::invalid_argument);
  J(1, 2) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(opspace::directions(J), std::invalid_argument);
  CHECK_THROWS_AS(opspace::singularity_type(J, H, Eigen::Vector3d::UnitX()), std::invalid_argument);
  const opspace::Model rrr = opspace::load_urdf(opspace::robot_path("rrr.urdf"));
  opspace::Data data(rrr);
  Eigen::MatrixXd wrong(6, 3);
  CHECK_THROWS_AS(opspace::point_position_hessian(rrr, data, 0, Eigen::Vector3d::Zero(), wrong),
                  std::invalid_argument);
}
