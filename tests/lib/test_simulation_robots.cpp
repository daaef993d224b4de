// The Bullet simulation of the shipped robots against our own model (kinematics.hpp,
// dynamics.hpp): two independent implementations of the same URDF, which must agree.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/simulation/simulation.hpp"
#include "opspace/model/urdf.hpp"
#include "grader/suite/random.hpp"

using opspace::Data;
using opspace::Integrator;
using opspace::Model;
using opspace::Simulation;
using opspace::SimulationSettings;

namespace {

const std::string kRobots[] = {"pp.urdf", "puma.urdf", "iiwa7.urdf", "rrr.urdf"};

/// A random state inside the joint limits (velocities up to 1 rad/s or m/s).
struct State {
  Eigen::VectorXd q, qd, tau;
};
State random_state(const Model& m, opspace::testing::Random& rnd) {
  State s{Eigen::VectorXd(m.dof()), Eigen::VectorXd(m.dof()), Eigen::VectorXd(m.dof())};
  for (int i = 0; i < m.dof(); ++i) {
    const auto& b = m.bodies[i];
    s.q[i] = rnd.uniform(b.lower, b.upper);
    s.qd[i] = rnd.uniform(-1.0, 1.0);
    s.tau[i] = rnd.uniform(-0.5, 0.5) * b.effort;  // within the limits: nothing is clamped
  }
  return s;
}

double rel_error(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); }

/// b(q, qdot) from our A(q) alone, by the Christoffel identity b = Adot qdot - 1/2 d/dq (qdot^T A
/// qdot), with dA/dq_k by central differences (h = 1e-6: truncation ~1e-12, rounding ~1e-10
/// relative). Independent of our RNEA: it uses only CRBA, which Bullet confirms to 1e-15.
Eigen::VectorXd christoffel_b(const Model& m, Data& d, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
  const int n = m.dof();
  const double h = 1e-6;
  Eigen::MatrixXd Adot = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd half_gradient(n);
  for (int k = 0; k < n; ++k) {
    Eigen::VectorXd qp = q, qm = q;
    qp[k] += h;
    qm[k] -= h;
    const Eigen::MatrixXd Ap = opspace::crba(m, d, qp);
    const Eigen::MatrixXd dA = (Ap - opspace::crba(m, d, qm)) / (2 * h);
    Adot += dA * qd[k];
    half_gradient[k] = 0.5 * qd.dot(dA * qd);
  }
  return Adot * qd - half_gradient;
}

/// Potential energy from our model: -sum m_i g . c_i with c_i from our forward kinematics.
double model_potential(const Model& m, Data& d, const Eigen::VectorXd& q) {
  opspace::forward_kinematics(m, d, q);
  double v = 0.0;
  for (int i = 0; i < m.dof(); ++i)
    v -= m.bodies[i].inertia.mass * m.gravity.dot(d.body_pose[i] * m.bodies[i].inertia.com);
  return v;
}

/// Calls body(file, model, data) on each robot of kRobots; a failure names the file.
template <class Body>
void each_robot(const Body& body) {
  for (const std::string& file : kRobots) {
    CAPTURE(file);
    const Model model = opspace::load_urdf(opspace::robot_path(file));
    Data data(model);
    body(file, model, data);
  }
}

}  // namespace

TEST_CASE("Bullet and our model agree on every robot: poses, mass matrix and one-step acceleration") {
  each_robot([&](const std::string& file, const Model& model, Data& data) {
    SimulationSettings settings;
    settings.integrator = Integrator::kEuler;
    Simulation sim(model, settings);
    opspace::testing::Random rnd(11);
    double worst_pose = 0, worst_A = 0, worst_qdd = 0;
    for (int trial = 0; trial < 20; ++trial) {
      const State s = random_state(model, rnd);
      sim.set_state(s.q, s.qd);

      opspace::forward_kinematics(model, data, s.q);
      for (int i = 0; i < model.dof(); ++i) {
        const Eigen::Isometry3d ours = data.body_pose[i], bullet = sim.body_pose(i);
        worst_pose = std::max(worst_pose, (ours.matrix() - bullet.matrix()).cwiseAbs().maxCoeff());
      }

      Eigen::MatrixXd Minv(model.dof(), model.dof());
      sim.inverse_mass_matrix(Minv);
      const Eigen::MatrixXd A = opspace::crba(model, data, s.q);
      worst_A = std::max(worst_A, rel_error(Minv.inverse(), A));

      const Eigen::VectorXd b = christoffel_b(model, data, s.q, s.qd);
      const Eigen::VectorXd g = opspace::generalized_gravity(model, data, s.q);
      const Eigen::VectorXd qdd = opspace::crba(model, data, s.q).llt().solve(s.tau - b - g);
      sim.step(s.tau);
      const Eigen::VectorXd measured = (sim.qdot() - s.qd) / settings.dt;
      worst_qdd = std::max(worst_qdd, rel_error(measured, qdd));
    }
    MESSAGE(file << ": worst pose difference " << worst_pose << ", A " << worst_A << " (relative), qdd "
                 << worst_qdd << " (relative)");
    // Poses: two chains of the same rotations, rounding only (bullet-notes measured 7e-16 m).
    CHECK_MESSAGE(worst_pose < 1e-12, "Bullet's link frames should be our forward kinematics");
    // A: the 1e-10. CRBA and Bullet's articulated-body inverse are exact algorithms;
    // the PUMA's tiny wrist inertias make A ill-conditioned, which the inversion amplifies.
    CHECK_MESSAGE(worst_A < 1e-10, "Bullet's M^-1, inverted, should be our A(q)");
    // qdd: the 1e-8 relative. A semi-implicit Euler step uses the acceleration at the
    // start of the step, which must equal A^-1 (tau - b - g); here b comes from our A through
    // the Christoffel identity (its difference quotients are good to ~1e-9).
    CHECK_MESSAGE(worst_qdd < 1e-8, "Bullet's one-step acceleration should be A^-1 (tau - b - g) of our model");
  });
}

// Two independent implementations of the same dynamics: Bullet's articulated-body step and
// our CRBA + RNEA (b, g) solved by Cholesky.
TEST_CASE("Bullet's one-step acceleration equals our forward_dynamics on every robot") {
  each_robot([&](const std::string& file, const Model& model, Data& data) {
    SimulationSettings settings;
    settings.integrator = Integrator::kEuler;
    Simulation sim(model, settings);
    opspace::testing::Random rnd(11);
    double worst = 0;
    for (int trial = 0; trial < 20; ++trial) {
      const State s = random_state(model, rnd);
      sim.set_state(s.q, s.qd);
      const Eigen::VectorXd qdd = opspace::forward_dynamics(model, data, s.q, s.qd, s.tau);
      sim.step(s.tau);
      worst = std::max(worst, rel_error((sim.qdot() - s.qd) / settings.dt, qdd));
    }
    MESSAGE(file << ": forward_dynamics vs Bullet, worst relative difference " << worst);
    // The 1e-8 relative (see the test above for the reason).
    CHECK_MESSAGE(worst < 1e-8, "Bullet's one-step acceleration should be opspace::forward_dynamics");
  });
}

TEST_CASE("Torques g(q) hold every robot still for 5 s") {
  each_robot([&](const std::string& file, const Model& model, Data& data) {
    Simulation sim(model);
    opspace::testing::Random rnd(12);
    const Eigen::VectorXd q0 = random_state(model, rnd).q;
    sim.set_state(q0, Eigen::VectorXd::Zero(model.dof()));
    for (int i = 0; i < 5000; ++i) sim.step(opspace::generalized_gravity(model, data, sim.q()));
    const double drift = (sim.q() - q0).cwiseAbs().maxCoeff();
    MESSAGE(file << ": drift after 5 s of tau = g(q): " << drift);
    // Our g balances Bullet's gravity to rounding (~1e-15 relative); an error e in the
    // acceleration drifts q by e t^2 / 2, so 1e-9 rad over 5 s allows e ~ 1e-10 rad/s^2.
    CHECK_MESSAGE(drift < 1e-9, "a robot fed its own gravity torques should not move");
  });
}

TEST_CASE("Zero torque conserves every robot's energy over 5 s of free motion") {
  each_robot([&](const std::string& file, const Model& model, Data& data) {
    Simulation sim(model);  // RK4, the default
    opspace::testing::Random rnd(13);
    const State s = random_state(model, rnd);
    sim.set_state(s.q, s.qd);

    // Bullet's energy against our model's: 0.5 qd^T A qd and -sum m g . c, rounding only.
    const opspace::Energy e0 = sim.energy();
    const double kinetic = 0.5 * s.qd.dot(opspace::crba(model, data, s.q) * s.qd);
    CHECK(e0.kinetic == doctest::Approx(kinetic).epsilon(1e-12));
    CHECK(e0.potential == doctest::Approx(model_potential(model, data, s.q)).epsilon(1e-12));

    // Scale: the energy the robot can trade, |V| plus kinetic energy; the potential's zero is
    // arbitrary, so the drift is measured against the largest kinetic energy reached.
    double worst = 0.0, max_kinetic = e0.kinetic, max_speed = 0.0;
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.dof());
    for (int i = 0; i < 5000; ++i) {
      sim.step(zero);
      const opspace::Energy e = sim.energy();
      worst = std::max(worst, std::abs(e.total() - e0.total()));
      max_kinetic = std::max(max_kinetic, e.kinetic);
      max_speed = std::max(max_speed, sim.qdot().cwiseAbs().maxCoeff());
    }
    MESSAGE(file << ": RK4, 1 ms, 5 s free motion: max kinetic energy " << max_kinetic << " J, worst energy drift "
                 << worst << " J (" << worst / max_kinetic << " relative), max joint speed " << max_speed);
    // Bound: 1e-5 of the kinetic energy reached. RK4's error per step is O(dt^5); measured: rrr
    // 3e-10, PUMA 5e-8, iiwa 6e-7 relative (docs/simulation.md); Euler gains percents.
    CHECK_MESSAGE(worst < 1e-5 * max_kinetic, "energy drift " << worst << " J");
  });
}

namespace {

struct Push {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // on the tool, from the plane, averaged
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // about the tool's body origin
  Eigen::Vector3d contact_point = Eigen::Vector3d::Zero();
  double drift = 0.0;
};

// The pusher's tool sphere rests on a plane under it; the arm applies tau = g + Jv^T F, Jv of
// the body-fixed point that touches the plane. At rest, the plane's reaction is -F there.
Push push(const Model& model, const Eigen::Vector3d& F) {
  Data data(model);
  Simulation sim(model);
  const int tool = model.frame_id("tool");
  const double radius = 0.03;  // the sphere of tests/data/sim/pusher.urdf
  Eigen::VectorXd q0(3);
  q0 << 0.3, 0.5, -1.6;  // forearm pointing down and out: the tool 0.14 m above the base
  opspace::forward_kinematics(model, data, q0);
  const Eigen::Isometry3d tool_pose = opspace::frame_pose(model, data, tool);
  const Eigen::Vector3d touch_world = tool_pose.translation() - radius * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d touch_local = tool_pose.inverse() * touch_world;
  sim.add_plane(Eigen::Vector3d::UnitZ(), touch_world.z(), {1.0, 0.0});
  sim.set_state(q0, Eigen::VectorXd::Zero(3));

  Push r;
  opspace::Matrix6Xd J(6, 3);
  const int steps = 2000, averaged = 500;
  for (int i = 0; i < steps; ++i) {
    opspace::forward_kinematics(model, data, sim.q());
    opspace::point_jacobian(model, data, tool, touch_local, J);
    const Eigen::VectorXd tau =
        opspace::generalized_gravity(model, data, sim.q()) + J.topRows<3>().transpose() * F;
    sim.step(tau);
    if (i >= steps - averaged) {
      r.force += sim.contact_wrench("tool").force / averaged;
      r.moment += sim.contact_wrench("tool").moment / averaged;
    }
  }
  REQUIRE_MESSAGE(!sim.contacts().empty(), "the tool should touch the plane");
  r.contact_point = sim.contacts().front().position_on_body;
  const Eigen::Vector3d origin = sim.body_pose(model.frames[tool].body).translation();
  r.moment -= (r.contact_point - origin).cross(r.force);  // what is not explained by one point
  r.drift = (sim.q() - q0).norm();
  return r;
}

}  // namespace

TEST_CASE("A tool pressed on a plane with tau = g + J^T F reads back F through the contact force") {
  const Model model = opspace::load_urdf(std::string(OPSPACE_TEST_DATA_DIR) + "/sim/pusher.urdf");
  // A pure push, and one with a tangential part (|Ft| = 6.4 N) that friction (mu = 1) holds.
  for (const Eigen::Vector3d& F : {Eigen::Vector3d(0, 0, -20), Eigen::Vector3d(5, -4, -30)}) {
    CAPTURE(F.transpose());
    const Push r = push(model, F);
    const double err = (r.force + F).norm() / F.norm();
    MESSAGE("F = " << F.transpose() << ": reaction " << r.force.transpose() << ", relative error " << err
                   << ", drift " << r.drift);
    // 1%: the bound. At rest, statics makes the reaction exactly -F.
    CHECK_MESSAGE(err < 0.01, "the plane's reaction should be -F");
    // The moment about the body origin is that of the force at the contact point (mm-level
    // lever arm errors at most: 1e-3 m times the force).
    CHECK_MESSAGE(r.moment.norm() < 1e-3 * F.norm(), "moment not explained by the contact point: "
                                                         << r.moment.transpose());
    CHECK_MESSAGE(r.drift < 1e-4, "the pressed arm should stay where it is");
  }
}
