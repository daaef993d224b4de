// Dynamics of every model in robots/ (and the test-only DH PUMA and tilted-axes tree), checked
// against identities that hold for any rigid-body tree, against the PP robot's closed form, and
// against the Robotics Toolbox's published PUMA 560 gravity torques.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/algorithms/pp_robot.hpp"
#include "opspace/math/constants.hpp"
#include "opspace/model/urdf.hpp"
#include "grader/suite/random.hpp"

using namespace opspace;
using opspace::testing::Random;

namespace {

constexpr double kStep = 1e-6;  // central differences: truncation ~ h^2, round-off ~ 1e-16 / h
constexpr int kTrials = 25;

std::vector<std::string> all_models() {
  return {robot_path("pp.urdf"), robot_path("puma.urdf"), robot_path("iiwa7.urdf"),
          robot_path("rrr.urdf"), std::string(OPSPACE_TEST_DATA_DIR) + "/puma_dh.urdf",
          std::string(OPSPACE_TEST_DATA_DIR) + "/tilted_axes.urdf"};  // tilted axes, a branch
}

Eigen::VectorXd random_q(const Model& model, Random& rng) {
  Eigen::VectorXd q(model.dof());
  for (int i = 0; i < model.dof(); ++i) {
    q(i) = model.bodies[i].type == JointType::kRevolute ? rng.uniform(-kPi, kPi) : rng.uniform(-1, 1);
  }
  return q;
}

/// The same robot without gravity, so that RNEA returns A qdd + b only.
Model without_gravity(Model model) {
  model.gravity.setZero();
  return model;
}

/// Centre of mass of body i, in the base frame (data holds the poses).
Eigen::Vector3d com_position(const Model& model, const Data& data, int i) {
  return data.body_pose[i] * model.bodies[i].inertia.com;
}

/// Potential energy V(q) = - sum_i m_i gravity . c_i  (the fixed base does not move).
double potential_energy(const Model& model, Data& data, const Eigen::VectorXd& q) {
  forward_kinematics(model, data, q);
  double V = 0.0;
  for (int i = 0; i < model.dof(); ++i) V -= model.bodies[i].inertia.mass * model.gravity.dot(com_position(model, data, i));
  return V;
}

/// Relative size of an error: |E| / max(1, |reference|).
double relative(const Eigen::MatrixXd& E, const Eigen::MatrixXd& reference) {
  return E.norm() / std::max(1.0, reference.norm());
}

/// Calls trial(model, data) kTrials times on each model of all_models() (without gravity when
/// `gravity` is false); a failure names the file.
template <class Trial>
void each_model(const Trial& trial, bool gravity = true) {
  for (const std::string& file : all_models()) {
    const Model model = gravity ? load_urdf(file) : without_gravity(load_urdf(file));
    Data data(model);
    CAPTURE(file);
    for (int t = 0; t < kTrials; ++t) trial(model, data);
  }
}

}  // namespace

TEST_CASE("the mass matrix is symmetric positive definite") {
  Random rng(401);
  each_model([&](const Model& model, Data& data) {
    const Eigen::MatrixXd& A = crba(model, data, random_q(model, rng));
    CHECK_MESSAGE((A - A.transpose()).norm() < 1e-12 * A.norm(), "A = A^T: kinetic energy is a quadratic form");
    CHECK_MESSAGE(Eigen::LLT<Eigen::MatrixXd>(A).info() == Eigen::Success,
                  "A > 0: every motion of the joints has positive kinetic energy");
  });
}

TEST_CASE("the mass matrix sums each link's mass and rotational inertia seen through its Jacobians") {
  // A = sum_i m_i Jc_i^T Jc_i + Jw_i^T R_i I_i R_i^T Jw_i  (Jc: Jacobian of the link's COM).
  Random rng(402);
  each_model([&](const Model& model, Data& data) {
    const Eigen::MatrixXd A = crba(model, data, random_q(model, rng));
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(model.dof(), model.dof());
    Matrix6Xd J(6, model.dof());
    for (int i = 0; i < model.dof(); ++i) {
      const Inertia& in = model.bodies[i].inertia;
      point_jacobian(model, data, model.frame_id(model.bodies[i].link_name), in.com, J);
      const Eigen::Matrix3d R = data.body_pose[i].linear();
      sum += in.mass * J.topRows<3>().transpose() * J.topRows<3>() +
             J.bottomRows<3>().transpose() * R * in.inertia * R.transpose() * J.bottomRows<3>();
    }
    CHECK_MESSAGE(relative(A - sum, A) < 1e-12, "CRBA disagrees with the Jacobian sum over the links");
  });
}

TEST_CASE("column i of the mass matrix is the torque of a unit acceleration of joint i") {
  // With gravity off and qdot = 0, RNEA(q, 0, qdd) = A qdd, so A e_i = RNEA(q, 0, e_i) - RNEA(q, 0, 0).
  Random rng(403);
  each_model(
      [&](const Model& model, Data& data) {
        const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.dof());
        const Eigen::VectorXd q = random_q(model, rng);
        const Eigen::MatrixXd A = crba(model, data, q);
        const Eigen::VectorXd tau0 = rnea(model, data, q, zero, zero);
        for (int i = 0; i < model.dof(); ++i) {
          const Eigen::VectorXd Ai = rnea(model, data, q, zero, Eigen::VectorXd::Unit(model.dof(), i)) - tau0;
          CAPTURE(i);
          CHECK_MESSAGE(relative(A.col(i) - Ai, A) < 1e-12, "CRBA and RNEA disagree on column ", i, " of A");
        }
      },
      /*gravity=*/false);
}

TEST_CASE("the gravity torques are the gradient of the potential energy") {
  // g(q) = dV/dq with V = - sum m_i gravity . c_i, by central differences.
  Random rng(404);
  each_model([&](const Model& model, Data& data) {
    const Eigen::VectorXd q = random_q(model, rng);
    const Eigen::VectorXd g = generalized_gravity(model, data, q);
    Eigen::VectorXd dV(model.dof());
    for (int i = 0; i < model.dof(); ++i) {
      const Eigen::VectorXd h = kStep * Eigen::VectorXd::Unit(model.dof(), i);
      dV(i) = (potential_energy(model, data, q + h) - potential_energy(model, data, q - h)) / (2 * kStep);
    }
    CHECK_MESSAGE(relative(g - dV, g) < 1e-7, "g is not dV/dq: gravity enters RNEA wrongly");
  });
}

TEST_CASE("half qdot^T A qdot is the sum of the links' kinetic energies") {
  // T = sum_i 1/2 m_i |v_ci|^2 + 1/2 w_i^T R_i I_i R_i^T w_i, with v_ci, w_i from point_velocity.
  Random rng(405);
  each_model([&](const Model& model, Data& data) {
    const Eigen::VectorXd qdot = rng.vector(model.dof(), -2, 2);
    const Eigen::MatrixXd A = crba(model, data, random_q(model, rng));
    double T = 0.0;
    for (int i = 0; i < model.dof(); ++i) {
      const Inertia& in = model.bodies[i].inertia;
      const Vector6d V = point_velocity(model, data, model.frame_id(model.bodies[i].link_name), in.com, qdot);
      const Eigen::Matrix3d R = data.body_pose[i].linear();
      T += 0.5 * in.mass * V.head<3>().squaredNorm() + 0.5 * V.tail<3>().dot(R * in.inertia * R.transpose() * V.tail<3>());
    }
    CHECK(0.5 * qdot.dot(A * qdot) == doctest::Approx(T).epsilon(1e-12));
  });
}

TEST_CASE("dA/dt - 2C is skew-symmetric") {
  // b(q, qdot) = C(q, qdot) qdot is quadratic in qdot. Its polarization
  //   B(u, w) = [b(q, u + w) - b(q, u - w)] / 4
  // is the symmetric Christoffel form, so C e_j = B(qdot, e_j) is the Christoffel C, for which
  // dA/dt - 2C is skew. dA/dt = [A(q + h qdot) - A(q - h qdot)] / 2h.
  Random rng(406);
  each_model([&](const Model& model, Data& data) {
    const int n = model.dof();
    const Eigen::VectorXd q = random_q(model, rng);
    const Eigen::VectorXd qdot = rng.vector(n, -2, 2);
    const Eigen::MatrixXd Ap = crba(model, data, q + kStep * qdot);
    const Eigen::MatrixXd Am = crba(model, data, q - kStep * qdot);
    const Eigen::MatrixXd Adot = (Ap - Am) / (2 * kStep);
    Eigen::MatrixXd C(n, n);
    for (int j = 0; j < n; ++j) {
      const Eigen::VectorXd ej = Eigen::VectorXd::Unit(n, j);
      const Eigen::VectorXd bp = coriolis_centrifugal(model, data, q, qdot + ej);
      C.col(j) = (bp - coriolis_centrifugal(model, data, q, qdot - ej)) / 4;
    }
    CHECK_MESSAGE((C * qdot - coriolis_centrifugal(model, data, q, qdot)).norm() < 1e-10 * std::max(1.0, C.norm()),
                  "C qdot must give back b");
    const Eigen::MatrixXd N = Adot - 2 * C;
    CHECK_MESSAGE(relative(N + N.transpose(), Adot) < 1e-7,
                  "dA/dt - 2C is not skew: b and A do not come from the same kinetic energy");
  });
}

TEST_CASE("forward dynamics inverts inverse dynamics") {
  // qdd = FD(q, qdot, tau) must satisfy RNEA(q, qdot, qdd) = tau.
  Random rng(407);
  each_model([&](const Model& model, Data& data) {
    const Eigen::VectorXd q = random_q(model, rng);
    const Eigen::VectorXd qdot = rng.vector(model.dof(), -2, 2);
    const Eigen::VectorXd tau = rng.vector(model.dof(), -10, 10);
    const Eigen::VectorXd qdd = forward_dynamics(model, data, q, qdot, tau);
    CHECK(relative(rnea(model, data, q, qdot, qdd) - tau, tau) < 1e-8);
    // And the pieces add up: tau = A qdd + b + g.
    const Eigen::VectorXd sum = crba(model, data, q) * qdd + coriolis_centrifugal(model, data, q, qdot) +
                                generalized_gravity(model, data, q);
    CHECK(relative(sum - tau, tau) < 1e-8);
  });
}

TEST_CASE("forward dynamics refuses a robot whose mass matrix is singular instead of returning NaN") {
  // With both PP links massless A(q) = 0: there is no acceleration to give (A qdd = tau has none).
  Model model = load_urdf(robot_path("pp.urdf"));
  for (auto& body : model.bodies) body.inertia = opspace::Inertia{};
  Data data(model);
  const Eigen::Vector2d zero = Eigen::Vector2d::Zero();
  CHECK_THROWS_WITH_AS(forward_dynamics(model, data, zero, zero, Eigen::Vector2d(1.0, 0.0)),
                       doctest::Contains("not positive definite"), std::invalid_argument);
}

TEST_CASE("the PP robot's mass matrix is the closed form of problem 1a") {
  // pp_robot.hpp: A = [[m1 + m2, m2], [m2, m2]] with m1 = 10, m2 = 5, whatever q.
  const Model model = load_urdf(robot_path("pp.urdf"));
  Data data(model);
  Random rng(408);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::MatrixXd& A = crba(model, data, rng.vector(2));
    CHECK_MESSAGE((A - pp::mass_matrix(pp::kM1, pp::kM2)).norm() < 1e-12, "pp.urdf's masses or axes are wrong");
  }
  // Both joints slide horizontally: gravity does no work along them.
  CHECK(generalized_gravity(model, data, Eigen::Vector2d(0.3, -0.2)).norm() < 1e-12);
}

TEST_CASE("the standard-DH PUMA 560 holds the Robotics Toolbox's published gravity torques") {
  // robots.md: Corke's Puma560 (standard DH, AKB 1986 inertials), g = 9.81, at
  // qn = (0, pi/4, pi, 0, pi/4, 0): gravload = (0, 31.6399, 6.0351, 0, 0.0283, 0) N m.
  // The toolbox prints four decimals, so agreement to 1e-4 N m.
  const Model model = load_urdf(std::string(OPSPACE_TEST_DATA_DIR) + "/puma_dh.urdf");
  Data data(model);
  Eigen::VectorXd qn(6);
  qn << 0, kPi / 4, kPi, 0, kPi / 4, 0;
  const Eigen::VectorXd published = (Eigen::VectorXd(6) << 0, 31.6399, 6.0351, 0, 0.0283, 0).finished();
  const Eigen::VectorXd& g = generalized_gravity(model, data, qn);
  CAPTURE(g.transpose());
  CHECK((g - published).cwiseAbs().maxCoeff() < 1e-4);
}

TEST_CASE("gravity can be set") {
  // g is linear in the gravity vector: doubling it doubles g, zeroing it zeroes g.
  Model model = load_urdf(robot_path("iiwa7.urdf"));
  Data data(model);
  const Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(7, -1, 1);
  const Eigen::VectorXd g1 = generalized_gravity(model, data, q);
  model.gravity *= 2;
  CHECK((generalized_gravity(model, data, q) - 2 * g1).norm() < 1e-12 * g1.norm());
  model.gravity.setZero();
  CHECK(generalized_gravity(model, data, q).norm() == 0.0);
}

TEST_CASE("a joint vector of the wrong size is refused with both sizes named") {
  const Model model = load_urdf(robot_path("puma.urdf"));
  Data data(model);
  CHECK_THROWS_WITH_AS(crba(model, data, Eigen::VectorXd::Zero(5)),
                       doctest::Contains("has 5 entries, but model 'puma'"), std::invalid_argument);
}
