// The operational-space matrices and the joint-space dynamics against numbers that others
// published for robots we rebuilt from their parameters, none of them computed by opspace:
// - sai2-model (github.com/manips-sai-org/sai2-model, the library of the course this problem set
//   comes from), sai2-model:tests/Tests_SaiModel.cpp at commit 2eaaf63: its robots are rebuilt in
//   tests/data/sai2/ and its expected matrices are printed to 6 significant digits;
// - Peter Corke's Robotics Toolbox for Python (github.com/petercorke/robotics-toolbox-python,
//   robotics-toolbox-python:tests/test_DHRobot.py at commit a9ed8d4) and for MATLAB
//   (github.com/petercorke/robotics-toolbox-matlab, unit_test/SerialLinkTest.m at commit
//   bd7a9d7): the Puma 560 in standard DH (tests/data/puma_dh.urdf) with its motors' reflected
//   inertia Jm G^2, printed to 4 decimals (a few to 6 significant digits).
// The tolerance of each comparison is the published precision: half a unit of the last printed
// digit (numbers printed to 4 decimals are within 5e-5 of the toolbox's double).
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/algorithms/opspace.hpp"
#include "opspace/math/constants.hpp"
#include "opspace/model/urdf.hpp"

using namespace opspace;

namespace {

std::string data_path(const std::string& file) { return std::string(OPSPACE_TEST_DATA_DIR) + "/" + file; }

/// Half a unit of the 6th significant digit of `printed` (std::cout's default precision, which
/// sai2-model's expected values were copied from). An entry printed as 0 is taken to the finest
/// place printed for numbers below 1 (1e-6). The factor 1 + 1e-9 absorbs the rounding of the
/// printed decimal itself into a double.
double six_digit_tolerance(double printed) {
  if (printed == 0.0) return 0.5e-6;
  return 0.5 * std::pow(10.0, std::floor(std::log10(std::abs(printed))) - 5) * (1 + 1e-9);
}

/// Largest |computed - published| relative to the published precision: < 1 means that every
/// entry rounds to the published one. The largest absolute difference goes to `max_abs`.
double worst_six_digit(const Eigen::MatrixXd& computed, const Eigen::MatrixXd& published, double& max_abs) {
  REQUIRE(computed.rows() == published.rows());
  REQUIRE(computed.cols() == published.cols());
  double worst = 0.0;
  max_abs = 0.0;
  for (Eigen::Index i = 0; i < published.size(); ++i) {
    const double d = std::abs(computed(i) - published(i));
    max_abs = std::max(max_abs, d);
    worst = std::max(worst, d / six_digit_tolerance(published(i)));
  }
  return worst;
}

// Checks `computed` against `published` to its six printed digits, and reports the largest
// difference under `what`.
void check_six_digits(const char* what, const Eigen::MatrixXd& computed, const Eigen::MatrixXd& published) {
  double max_abs = 0.0;
  CHECK_MESSAGE(worst_six_digit(computed, published, max_abs) < 1.0, what << " differs beyond the published digits");
  MESSAGE(what << ": largest difference " << max_abs);
}

/// The same for numbers printed to 4 decimals (the toolbox's tests): half of 1e-4, with the
/// same margin for the decimal's rounding.
constexpr double kFourDecimals = 0.5e-4 * (1 + 1e-9);

Eigen::MatrixXd row_major(int rows, int cols, std::initializer_list<double> values) {
  REQUIRE(static_cast<int>(values.size()) == rows * cols);
  Eigen::MatrixXd M(rows, cols);
  auto it = values.begin();
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) M(r, c) = *it++;
  return M;
}

/// The robot's A, J0 of `point` on `frame`, and g at q.
struct At {
  Eigen::MatrixXd A;
  Eigen::MatrixXd J0;
  Eigen::VectorXd g;
};

At evaluate(const Model& model, const Eigen::VectorXd& q, const std::string& frame, const Eigen::Vector3d& point) {
  Data data(model);
  At at;
  at.A = crba(model, data, q);
  at.g = generalized_gravity(model, data, q);
  forward_kinematics(model, data, q);
  Matrix6Xd J0(6, model.dof());
  point_jacobian(model, data, model.frame_id(frame), point, J0);
  at.J0 = J0;
  return at;
}

// ---- sai2-model ------------------------------------------------------------------------------

/// The rpsprbot at SetNewQSphericalModel's configuration: q(0) = 0.2, q(1) = 0.5, the spherical
/// joint at the rotation built into the file (its three revolute joints at 0), q(5) = -0.2,
/// q(6) = 0.4. Task: J of point (0.1, 0.2, 0.5) on link4 (the tests' link_name, pos_in_link).
struct Rpsprbot {
  Model model = load_urdf(data_path("sai2/rpsprbot_at_test_rotation.urdf"));
  Eigen::VectorXd q = (Eigen::VectorXd(7) << 0.2, 0.5, 0, 0, 0, -0.2, 0.4).finished();
  At at = evaluate(model, q, "link4", Eigen::Vector3d(0.1, 0.2, 0.5));
};

}  // namespace

TEST_CASE("the rebuilt sai2 rpsprbot turns its spherical joint by pi/4 about (1, 1, 1)/sqrt(3)") {
  // The fixed joint's rpy in the file stands for the published quaternion: its rotation must be
  // that one to rounding (1e-15), or the comparisons below would test another configuration.
  const Model model = load_urdf(data_path("sai2/rpsprbot_at_test_rotation.urdf"));
  Data data(model);
  forward_kinematics(model, data, Eigen::VectorXd::Zero(model.dof()));
  const Eigen::Matrix3d R = (frame_pose(model, data, model.frame_id("link1")).inverse() *
                             frame_pose(model, data, model.frame_id("link2")))
                                .linear();
  const Eigen::Matrix3d expected =
      Eigen::AngleAxisd(kPi / 4, Eigen::Vector3d(1, 1, 1).normalized()).toRotationMatrix();
  CHECK((R - expected).cwiseAbs().maxCoeff() < 1e-15);
}

TEST_CASE("the rebuilt sai2 rpsprbot's Jw matches sai2-model's at the spherical test rotation") {
  // Tests_SaiModel.cpp, TEST_F(SaiModelTest, Jw), "other joint configuration": the base-frame
  // angular Jacobian of link4 (its base move is a translation and a rotation about x, which the
  // Jw in the robot's own base frame does not see). Kinematic evidence that the three revolute
  // joints stand for the spherical joint's velocity coordinates, column for column.
  const Rpsprbot robot;
  const Eigen::MatrixXd published = row_major(3, 7, {1, 0, 0.804738, -0.310617, 0.505879, 0, -0.310617,  //
                                                     0, 0, 0.557506, 0.688194, -0.464302, 0, 0.688194,   //
                                                     0, 0, -0.203923, 0.655672, 0.726987, 0, 0.655672});
  check_six_digits("sai2 Jw", robot.at.J0.bottomRows(3), published);
}

TEST_CASE("the 6x6 task inertia of the sai2 rpsprbot matches sai2-model's published Lambda") {
  // Tests_SaiModel.cpp, TEST_F(SaiModelTest, TaskInertia): Lambda of the 6-D task J at link4.
  const Rpsprbot robot;
  TaskSpace ts(6, 7);
  operational_space(robot.at.A, robot.at.J0, robot.at.g, ts);
  const Eigen::MatrixXd published = row_major(
      6, 6,
      {2.45598,   -0.388523, -0.565437, -0.591744, -1.4949,  0.525617,  //
       -0.388523, 3.1234,    0.987834,  2.07603,   1.21213,  -1.48404,  //
       -0.565437, 0.987834,  3.02436,   1.04979,   2.05066,  -0.684001, //
       -0.591744, 2.07603,   1.04979,   2.19218,   1.52106,  -1.12447,  //
       -1.4949,   1.21213,   2.05066,   1.52106,   2.4057,   -1.01646,  //
       0.525617,  -1.48404,  -0.684001, -1.12447,  -1.01646, 1.0047});
  CHECK(ts.rank == 6);
  check_six_digits("sai2 Lambda (6x6)", ts.Lambda, published);
}

TEST_CASE("the 7x6 dynamically consistent inverse of the sai2 rpsprbot matches sai2-model's Jbar") {
  // Tests_SaiModel.cpp, TEST_F(SaiModelTest, DynConsistentJacobian).
  const Rpsprbot robot;
  TaskSpace ts(6, 7);
  operational_space(robot.at.A, robot.at.J0, robot.at.g, ts);
  const Eigen::MatrixXd published = row_major(
      7, 6,
      {0.157377,   -0.414018, -0.373932, -0.49165,  -0.460724, 0.268614,   //
       -0.238489,  0.372479,  0.403845,  0.483299,  0.510137,  -0.263651,  //
       -0.126647,  0.333176,  0.300917,  1.20039,   0.928268,  -0.420086,  //
       1.11148,    0.320198,  -0.568935, -0.141244, -0.860789, 0.0720711,  //
       -0.0796136, 0.209443,  0.189164,  0.754595,  -0.231231, 0.5911,     //
       0.624475,   -0.571149, 0.576222,  -0.409894, -0.10998,  0.315857,   //
       -1.0626,    -0.448799, 0.452785,  -0.322088, 1.40587,   0.667037});
  check_six_digits("sai2 Jbar (7x6)", ts.Jbar, published);
}

TEST_CASE("the 7x7 null-space projector of the sai2 rpsprbot matches sai2-model's N") {
  // Tests_SaiModel.cpp, TEST_F(SaiModelTest, Nullspace): N = I - Jbar J.
  const Rpsprbot robot;
  TaskSpace ts(6, 7);
  operational_space(robot.at.A, robot.at.J0, robot.at.g, ts);
  const Eigen::MatrixXd published = row_major(
      7, 7,
      {0.272981,  0.284225,  0, 0.0223339,  0, 0, 0,  //
       0.651376,  0.678205,  0, 0.0532922,  0, 0, 0,  //
       -0.219678, -0.228727, 0, -0.017973,  0, 0, 0,  //
       0.596632,  0.621207,  0, 0.0488134,  0, 0, 0,  //
       -0.138096, -0.143784, 0, -0.0112983, 0, 0, 0,  //
       -0.651376, -0.678205, 0, -0.0532922, 0, 0, 0,  //
       -0.51184,  -0.532922, 0, -0.0418761, 0, 0, 0});
  check_six_digits("sai2 N (7x7)", ts.N, published);
}

TEST_CASE("the sai2 2R arm's task inertia through the pseudo-inverse matches sai2-model's, singular and not") {
  // Tests_SaiModel.cpp, TEST_F(SaiModelTest, TaskInertiaPseudoInv): the (y, z) rows of Jv of point
  // (0, 0, 0.3) on link1. At q = 0 the arm points up: the z row is zero, J A^-1 J^T has a zero
  // eigenvalue, and sai2-model's SVD pseudo-inverse gives Lambda = [[1.59467, 0], [0, 0]]; our
  // eigenvalue cut-off drops the same direction. At q2 = 0.5 both directions are kept and the
  // plain inverse and the pseudo-inverse agree: [[1.6, 0.816951], [0.816951, 5.90864]].
  const Model model = load_urdf(data_path("sai2/rrbot.urdf"));
  TaskSpace ts(2, 2);
  double max_abs = 0.0;
  SUBCASE("at the singular q = 0") {
    const At at = evaluate(model, Eigen::Vector2d(0, 0), "link1", Eigen::Vector3d(0, 0, 0.3));
    operational_space(at.A, at.J0.middleRows(1, 2), at.g, ts);
    CHECK(ts.rank == 1);
    CHECK(worst_six_digit(ts.Lambda, row_major(2, 2, {1.59467, 0, 0, 0}), max_abs) < 1.0);
    MESSAGE("sai2 singular Lambda: largest difference " << max_abs);
  }
  SUBCASE("at q = (0, 0.5)") {
    const At at = evaluate(model, Eigen::Vector2d(0, 0.5), "link1", Eigen::Vector3d(0, 0, 0.3));
    operational_space(at.A, at.J0.middleRows(1, 2), at.g, ts);
    CHECK(ts.rank == 2);
    CHECK(worst_six_digit(ts.Lambda, row_major(2, 2, {1.6, 0.816951, 0.816951, 5.90864}), max_abs) < 1.0);
    MESSAGE("sai2 regular Lambda: largest difference " << max_abs);
  }
}

TEST_CASE("the sai2 RRP arm's mass matrix and gravity torques match sai2-model's") {
  // Tests_SaiModel.cpp, TEST_F(SaiModelTest, UpdateModel): M at q = 0 and at (0.1, 0.2, 0.3);
  // TEST_F(SaiModelTest, JointGravity): the joint gravity vector (which sai2-model defines with
  // the sign of ours, the torque that holds the robot) at the same two configurations, g = 9.81.
  const Model model = load_urdf(data_path("sai2/rrpbot.urdf"));
  double max_abs = 0.0;
  const At zero = evaluate(model, Eigen::Vector3d(0, 0, 0), "link2", Eigen::Vector3d::Zero());
  CHECK(worst_six_digit(zero.A, row_major(3, 3, {5.3, 2.2, 0, 2.2, 1.2, 0, 0, 0, 1}), max_abs) < 1.0);
  CHECK(worst_six_digit(zero.g, Eigen::Vector3d(0, 0, 9.81), max_abs) < 1.0);
  const At moved = evaluate(model, Eigen::Vector3d(0.1, 0.2, 0.3), "link2", Eigen::Vector3d::Zero());
  CHECK(worst_six_digit(moved.A, row_major(3, 3, {6.53817, 3.16409, 0.198669, 3.16409, 1.89, 0, 0.198669, 0, 1.0}),
                        max_abs) < 1.0);
  MESSAGE("sai2 A (RRP): largest difference " << max_abs);
}

// ---- the Robotics Toolbox's Puma 560 ---------------------------------------------------------

namespace {

/// tests/data/puma_dh.urdf with the toolbox's motors: Puma560.py (and mdl_puma560.m) give each
/// link Jm (kg m^2) and G; the armature is Jm G^2, which the toolbox's inertia() adds to the
/// diagonal (its rne adds Jm G^2 qdd_i to joint i's torque).
Model toolbox_puma() {
  Model model = load_urdf(data_path("puma_dh.urdf"));
  const double Jm[6] = {200e-6, 200e-6, 200e-6, 33e-6, 33e-6, 33e-6};
  const double G[6] = {-62.6111, 107.815, -53.7063, 76.0364, 71.923, 76.686};
  for (int i = 0; i < 6; ++i) model.bodies[i].armature = Jm[i] * G[i] * G[i];
  return model;
}

Eigen::VectorXd toolbox_qn() { return (Eigen::VectorXd(6) << 0, kPi / 4, kPi, 0, kPi / 4, 0).finished(); }

/// The toolbox's Coriolis matrix (robotics-toolbox-python, Dynamics.coriolis): from RNEA with
/// gravity off and no friction, Csq(:, i) = b(e_i), and for each pair i < j the product term
/// P = b(e_i + e_j) - Csq(:, i) - Csq(:, j) shared half and half: C(:, j) += P qd_i / 2,
/// C(:, i) += P qd_j / 2; then C += Csq diag(qd). Any C with C qd = b is not unique: this is theirs.
Eigen::MatrixXd toolbox_coriolis(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
  Data data(model);
  const int n = model.dof();
  Eigen::MatrixXd Csq(n, n), C = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) Csq.col(i) = coriolis_centrifugal(model, data, q, Eigen::VectorXd::Unit(n, i));
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const Eigen::VectorXd P = coriolis_centrifugal(model, data, q, Eigen::VectorXd::Unit(n, i) + Eigen::VectorXd::Unit(n, j)) -
                                Csq.col(i) - Csq.col(j);
      C.col(j) += P * qd(i) / 2;
      C.col(i) += P * qd(j) / 2;
    }
  }
  return C + Csq * qd.asDiagonal();
}

double max_abs_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).cwiseAbs().maxCoeff(); }

}  // namespace

TEST_CASE("the Puma 560 with its motors' armature has the Robotics Toolbox's published inertia at qn") {
  // test_DHRobot.py, test_inertia: puma.inertia(puma.qn), 4 decimals. Without the armature the
  // diagonal would be short by Jm G^2 (0.78 kg m^2 on joint 1, 2.3 on joint 2).
  const Model model = toolbox_puma();
  const Eigen::MatrixXd published = row_major(6, 6,
                                              {3.6594,  -0.4044, 0.1006, -0.0025, 0.0000, -0.0000,  //
                                               -0.4044, 4.4137,  0.3509, 0.0000,  0.0024, 0.0000,   //
                                               0.1006,  0.3509,  0.9378, 0.0000,  0.0015, 0.0000,   //
                                               -0.0025, 0.0000,  0.0000, 0.1925,  0.0000, 0.0000,   //
                                               0.0000,  0.0024,  0.0015, 0.0000,  0.1713, 0.0000,   //
                                               -0.0000, 0.0000,  0.0000, 0.0000,  0.0000, 0.1941});
  const At at = evaluate(model, toolbox_qn(), "link6", Eigen::Vector3d::Zero());
  const double d = max_abs_difference(at.A, published);
  CHECK(d < kFourDecimals);
  MESSAGE("toolbox A at qn: largest difference " << d);
}

TEST_CASE("the Puma 560's task inertia at its end-effector is the toolbox's published Cartesian inertia") {
  // test_DHRobot.py, test_inertia_x: inertia_x(qn, representation=None) = J0^-T A J0^-1 with J0
  // the geometric Jacobian [v; w] of the DH frame 6 origin in the base frame. J0 is square and
  // regular at qn, so (J0 A^-1 J0^T)^-1 is the same matrix.
  const Model model = toolbox_puma();
  const At at = evaluate(model, toolbox_qn(), "link6", Eigen::Vector3d::Zero());
  TaskSpace ts(6, 6);
  operational_space(at.A, at.J0, at.g, ts);
  const Eigen::MatrixXd published = row_major(6, 6,
                                              {17.2954, -2.7542, -9.6233, -0.0000, 0.2795,  0.0000,   //
                                               -2.7542, 12.1909, 1.2459,  -0.3254, -0.0703, -0.9652,  //
                                               -9.6233, 1.2459,  13.3348, -0.0000, 0.2767,  -0.0000,  //
                                               -0.0000, -0.3254, -0.0000, 0.1941,  0.0000,  0.1941,   //
                                               0.2795,  -0.0703, 0.2767,  0.0000,  0.1713,  0.0000,   //
                                               0.0000,  -0.9652, -0.0000, 0.1941,  0.0000,  0.5791});
  CHECK(ts.rank == 6);
  const double d = max_abs_difference(ts.Lambda, published);
  CHECK(d < kFourDecimals);
  MESSAGE("toolbox Lambda at qn: largest difference " << d);
}

TEST_CASE("the Puma 560's Coriolis matrix, inertial torques and inverse dynamics match the toolbox's at qn") {
  const Model model = toolbox_puma();
  const Eigen::VectorXd qn = toolbox_qn();
  Data data(model);
  const Eigen::VectorXd ramp = (Eigen::VectorXd(6) << 1, 2, 3, 1, 2, 3).finished();
  SUBCASE("coriolis(qn, qd = (1, 2, 3, 1, 2, 3)): test_DHRobot.py, test_coriolis, 4 decimals") {
    const Eigen::MatrixXd published = row_major(6, 6,
                                                {-0.1735, -2.0494, -0.1178, -0.0002, -0.0045, 0.0001,   //
                                                 0.6274,  1.1572,  1.9287,  -0.0015, -0.0003, -0.0000,  //
                                                 -0.3608, -0.7734, -0.0018, -0.0009, -0.0064, -0.0000,  //
                                                 0.0011,  0.0005,  -0.0001, 0.0002,  0.0002,  -0.0001,  //
                                                 -0.0002, 0.0028,  0.0046,  -0.0002, -0.0000, -0.0000,  //
                                                 0.0001,  0.0000,  0.0000,  0.0000,  0.0000,  0});
    const double d = max_abs_difference(toolbox_coriolis(model, qn, ramp), published);
    CHECK(d < kFourDecimals);
    MESSAGE("toolbox C at qn: largest difference " << d);
  }
  SUBCASE("itorque(qn, qdd = (1, 2, 3, 1, 2, 3)) = A qdd: test_DHRobot.py, test_itorque, 4 decimals") {
    const Eigen::VectorXd published = (Eigen::VectorXd(6) << 3.1500, 9.4805, 3.6189, 0.1901, 0.3519, 0.5823).finished();
    const Eigen::VectorXd& gravity_and_inertial = rnea(model, data, qn, Eigen::VectorXd::Zero(6), ramp);
    const Eigen::VectorXd inertial = gravity_and_inertial - generalized_gravity(model, data, qn);
    const double d = max_abs_difference(inertial, published);
    CHECK(d < kFourDecimals);
    MESSAGE("toolbox itorque at qn: largest difference " << d);
  }
  SUBCASE("rne(qn, qd = 0, qdd = 1) = g + A 1: test_DHRobot.py, test_rne, tr1 (6 significant digits)") {
    // At rest the toolbox's friction (Coulomb and viscous) is zero, so this is rigid-body
    // dynamics plus the rotors' Jm G^2 qdd alone.
    const Eigen::VectorXd published =
        (Eigen::VectorXd(6) << 3.35311, 36.0025, 7.42596, 0.190043, 0.203441, 0.194133).finished();
    double max_abs = 0.0;
    CHECK(worst_six_digit(rnea(model, data, qn, Eigen::VectorXd::Zero(6), Eigen::VectorXd::Ones(6)), published,
                          max_abs) < 1.0);
    MESSAGE("toolbox rne at qn: largest difference " << max_abs);
  }
}

TEST_CASE("the Puma 560's manipulability at qn is the toolbox's, by Yoshikawa's and by Asada's measure") {
  // test_DHRobot.py, test_yoshi: sqrt(det(J J^T)) of J0 (|det J0|, square), of its translational
  // rows and of its rotational rows: 0.0786 (4 decimals), 0.111181 and 2.44949 (6 digits).
  // test_asada: min/max eigenvalue of the Cartesian inertia J0^-T A J0^-1, of all of it and of
  // its translational and rotational diagonal blocks: 0.0044, 0.2094, 0.1716 (4 decimals).
  const Model model = toolbox_puma();
  const At at = evaluate(model, toolbox_qn(), "link6", Eigen::Vector3d::Zero());
  const auto yoshikawa = [](const Eigen::MatrixXd& J) { return std::sqrt(std::abs((J * J.transpose()).determinant())); };
  CHECK(std::abs(yoshikawa(at.J0) - 0.0786) < kFourDecimals);
  CHECK(std::abs(yoshikawa(at.J0.topRows(3)) - 0.111181) < six_digit_tolerance(0.111181));
  CHECK(std::abs(yoshikawa(at.J0.bottomRows(3)) - 2.44949) < six_digit_tolerance(2.44949));

  TaskSpace ts(6, 6);
  operational_space(at.A, at.J0, at.g, ts);
  const auto asada = [](const Eigen::MatrixXd& Mx) {
    const Eigen::VectorXd e = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Mx).eigenvalues();
    return e.minCoeff() / e.maxCoeff();
  };
  const Eigen::MatrixXd Lambda = ts.Lambda;
  CHECK(std::abs(asada(Lambda) - 0.0044) < kFourDecimals);
  CHECK(std::abs(asada(Lambda.topLeftCorner(3, 3)) - 0.2094) < kFourDecimals);
  CHECK(std::abs(asada(Lambda.bottomRightCorner(3, 3)) - 0.1716) < kFourDecimals);
}

TEST_CASE("the Puma 560 at the MATLAB toolbox's test pose has its published inertia and Cartesian inertia") {
  // SerialLinkTest.m (robotics-toolbox-matlab), inertia_test and cinertia_test, at
  // q = (0, pi/4, -pi, 1, pi/4, 0) (its tests' own pose, with q4 = 1), 4 decimals.
  const Model model = toolbox_puma();
  const Eigen::VectorXd q = (Eigen::VectorXd(6) << 0, kPi / 4, -kPi, 1, kPi / 4, 0).finished();
  const At at = evaluate(model, q, "link6", Eigen::Vector3d::Zero());
  const Eigen::MatrixXd inertia = row_major(6, 6,
                                            {3.6591,  -0.4042, 0.1013,  -0.0021, -0.0015, -0.0000,  //
                                             -0.4042, 4.4128,  0.3504,  -0.0008, 0.0017,  0.0000,   //
                                             0.1013,  0.3504,  0.9377,  -0.0008, 0.0008,  0.0000,   //
                                             -0.0021, -0.0008, -0.0008, 0.1925,  0.0000,  0.0000,   //
                                             -0.0015, 0.0017,  0.0008,  0.0000,  0.1713,  0.0000,   //
                                             -0.0000, 0.0000,  0.0000,  0.0000,  0.0000,  0.1941});
  const Eigen::MatrixXd cinertia = row_major(6, 6,
                                             {18.0741, -2.2763, -8.8446, -0.0283, 0.7541,  -0.4015,  //
                                              -2.2763, 11.2461, 1.7238,  -0.0750, 0.2214,  -0.4733,  //
                                              -8.8446, 1.7238,  14.1135, -0.0300, 0.7525,  -0.4032,  //
                                              -0.0283, -0.0750, -0.0300, 0.1377,  -0.0171, 0.0492,   //
                                              0.7541,  0.2214,  0.7525,  -0.0171, 0.4612,  -0.2461,  //
                                              -0.4015, -0.4733, -0.4032, 0.0492,  -0.2461, 0.3457});
  TaskSpace ts(6, 6);
  operational_space(at.A, at.J0, at.g, ts);
  const double dA = max_abs_difference(at.A, inertia), dL = max_abs_difference(ts.Lambda, cinertia);
  CHECK(dA < kFourDecimals);
  CHECK(dL < kFourDecimals);
  MESSAGE("MATLAB toolbox A: largest difference " << dA << ", Lambda: " << dL);
}
