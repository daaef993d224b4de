// The Bullet simulation against closed forms of hand-built models: a planar two-link arm
// (Spong's textbook closed forms of A, b, g and J) and a single body with a full inertia tensor
// on a tilted axis. These need no URDF and no dynamics.cpp; test_simulation_robots.cpp checks
// the shipped robots against our own dynamics.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <string>

#include <BulletDynamics/Featherstone/btMultiBody.h>

#include "opspace/simulation/simulation.hpp"
#include "grader/suite/random.hpp"

using opspace::Body;
using opspace::Integrator;
using opspace::JointType;
using opspace::Model;
using opspace::Simulation;
using opspace::SimulationSettings;

namespace {

// The planar arm: joints about +y, links along the body x axis, gravity -z. Numbers chosen to
// look like a small arm; the principal moments satisfy the triangle inequality.
constexpr double kM1 = 2.0, kM2 = 1.5;    // kg
constexpr double kL1 = 0.5, kL2 = 0.4;    // m, joint 1 to joint 2, joint 2 to the tip
constexpr double kC1 = 0.25, kC2 = 0.2;   // m, joint to COM along the link
constexpr double kI1 = 0.05, kI2 = 0.02;  // kg m^2, about the joint axis (y) at the COM
constexpr double kBaseHeight = 1.0;       // m, joint 1 above the world origin
constexpr double kTipRadius = 0.02;       // m, the tip's collision sphere
constexpr double kG = 9.81;

Model two_link_arm(double effort1 = 0.0, double effort2 = 0.0) {
  Model m;
  m.name = "two_link_arm";
  m.source = "test_simulation.cpp";
  Body b1;
  b1.joint_name = "shoulder";
  b1.link_name = "upper";
  b1.parent = -1;
  b1.joint_placement.translation() = Eigen::Vector3d(0, 0, kBaseHeight);
  b1.axis = Eigen::Vector3d::UnitY();
  b1.inertia.mass = kM1;
  b1.inertia.com = Eigen::Vector3d(kC1, 0, 0);
  b1.inertia.inertia = Eigen::Vector3d(0.01, kI1, 0.045).asDiagonal();
  b1.effort = effort1;
  Body b2 = b1;
  b2.joint_name = "elbow";
  b2.link_name = "fore";
  b2.parent = 0;
  b2.joint_placement = Eigen::Isometry3d::Identity();
  b2.joint_placement.translation() = Eigen::Vector3d(kL1, 0, 0);
  b2.inertia.mass = kM2;
  b2.inertia.com = Eigen::Vector3d(kC2, 0, 0);
  b2.inertia.inertia = Eigen::Vector3d(0.005, kI2, 0.018).asDiagonal();
  b2.effort = effort2;
  m.bodies = {b1, b2};
  opspace::Shape tip;
  tip.kind = opspace::Shape::Kind::kSphere;
  tip.radius = kTipRadius;
  tip.body = 1;
  tip.placement.translation() = Eigen::Vector3d(kL2, 0, 0);
  tip.link = "fore";
  m.collisions = {tip};
  m.frames = {{"base", -1, Eigen::Isometry3d::Identity()},
              {"upper", 0, Eigen::Isometry3d::Identity()},
              {"fore", 1, Eigen::Isometry3d::Identity()},
              {"tip", 1, Eigen::Isometry3d(Eigen::Translation3d(kL2, 0, 0))}};
  return m;
}

// A rotation by +theta about +y maps the link's x axis to (cos, 0, -sin): the links hang
// below the shoulder for positive angles.
Eigen::Matrix2d arm_A(const Eigen::Vector2d& q) {
  const double c2 = std::cos(q[1]);
  Eigen::Matrix2d A;
  A(0, 0) = kI1 + kI2 + kM1 * kC1 * kC1 + kM2 * (kL1 * kL1 + kC2 * kC2 + 2 * kL1 * kC2 * c2);
  A(0, 1) = A(1, 0) = kI2 + kM2 * (kC2 * kC2 + kL1 * kC2 * c2);
  A(1, 1) = kI2 + kM2 * kC2 * kC2;
  return A;
}

Eigen::Vector2d arm_b(const Eigen::Vector2d& q, const Eigen::Vector2d& qd) {
  const double h = kM2 * kL1 * kC2 * std::sin(q[1]);
  return Eigen::Vector2d(-h * (2 * qd[0] * qd[1] + qd[1] * qd[1]), h * qd[0] * qd[0]);
}

// V = m g z with z_c1 = -c1 sin q1, z_c2 = -l1 sin q1 - c2 sin(q1 + q2); g = dV/dq.
Eigen::Vector2d arm_g(const Eigen::Vector2d& q) {
  const double c1 = std::cos(q[0]), c12 = std::cos(q[0] + q[1]);
  return Eigen::Vector2d(-kG * (kM1 * kC1 * c1 + kM2 * (kL1 * c1 + kC2 * c12)), -kG * kM2 * kC2 * c12);
}

Eigen::Vector3d arm_tip(const Eigen::Vector2d& q) {
  const double s1 = std::sin(q[0]), c1 = std::cos(q[0]);
  const double s12 = std::sin(q[0] + q[1]), c12 = std::cos(q[0] + q[1]);
  return Eigen::Vector3d(kL1 * c1 + kL2 * c12, 0, kBaseHeight - kL1 * s1 - kL2 * s12);
}

// Jv of the tip (3 x 2): the derivative of arm_tip.
Eigen::Matrix<double, 3, 2> arm_Jv(const Eigen::Vector2d& q) {
  const double s1 = std::sin(q[0]), c1 = std::cos(q[0]);
  const double s12 = std::sin(q[0] + q[1]), c12 = std::cos(q[0] + q[1]);
  Eigen::Matrix<double, 3, 2> J;
  J << -kL1 * s1 - kL2 * s12, -kL2 * s12, 0, 0, -kL1 * c1 - kL2 * c12, -kL2 * c12;
  return J;
}

// Jv of the body-fixed point of the forearm that touches a plane below: the tip centre moved
// by -r along z. A rotation about y moves it by w x (0, 0, -r) = (-r w, 0, 0) more than the
// centre; a friction force acts there, not at the centre.
Eigen::Matrix<double, 3, 2> arm_Jv_contact(const Eigen::Vector2d& q) {
  Eigen::Matrix<double, 3, 2> J = arm_Jv(q);
  J.row(0).array() -= kTipRadius;
  return J;
}

double rel_error(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); }

}  // namespace

TEST_CASE("Bullet's mass matrix of a two-link arm equals the textbook closed form") {
  Simulation sim(two_link_arm());
  opspace::testing::Random rnd(1);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::Vector2d q = rnd.vector(2, -3, 3), qd = rnd.vector(2, -2, 2);
    sim.set_state(q, qd);
    Eigen::MatrixXd Minv(2, 2);
    sim.inverse_mass_matrix(Minv);
    // 1e-10: two exact algorithms in double precision agree to ~1e-15 relative; the bound
    // leaves room for the conditioning of the inversion (cond(A) < 100 here).
    CHECK_MESSAGE(rel_error(Minv.inverse(), arm_A(q)) < 1e-10,
                  "Bullet's articulated-body M^-1 inverted should be A(q) of the closed form at q = "
                      << q.transpose());
  }
}

TEST_CASE("One Euler step of Bullet accelerates the arm by A^-1 (tau - b - g) of the closed form") {
  SimulationSettings s;
  s.integrator = Integrator::kEuler;
  Simulation sim(two_link_arm(), s);
  opspace::testing::Random rnd(2);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::Vector2d q = rnd.vector(2, -3, 3), qd = rnd.vector(2, -2, 2), tau = rnd.vector(2, -20, 20);
    sim.set_state(q, qd);
    sim.step(tau);
    const Eigen::Vector2d measured = (sim.qdot() - qd) / s.dt;
    const Eigen::Vector2d expected = arm_A(q).inverse() * (tau - arm_b(q, qd) - arm_g(q));
    // Semi-implicit Euler updates qdot with the acceleration at the start of the step, so the
    // two agree to rounding (bullet-notes measured 3e-13); 1e-8 is the bound.
    CHECK_MESSAGE(rel_error(measured, expected) < 1e-8,
                  "(qdot1 - qdot0)/dt = " << measured.transpose() << ", closed form " << expected.transpose());
  }
}

TEST_CASE("A body with a full inertia tensor on a tilted axis has the closed-form inertia and gravity torque") {
  // One body: tilted joint frame, tilted axis, off-axis COM, an inertia that is not diagonal in
  // the body frame. Bullet needs principal axes: this checks the diagonalisation and the frames.
  opspace::testing::Random rnd(3);
  Model m;
  m.name = "tilted";
  Body b;
  b.joint_name = "j";
  b.link_name = "l";
  b.joint_placement.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  b.joint_placement.translation() = Eigen::Vector3d(0.1, -0.2, 0.3);
  b.axis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  b.inertia.mass = 1.7;
  b.inertia.com = Eigen::Vector3d(0.1, -0.05, 0.2);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(1.1, Eigen::Vector3d(-2, 1, 0.5).normalized()).toRotationMatrix();
  b.inertia.inertia = R * Eigen::Vector3d(0.02, 0.03, 0.04).asDiagonal() * R.transpose();
  m.bodies = {b};
  SimulationSettings s;
  s.integrator = Integrator::kEuler;
  Simulation sim(m, s);
  const Eigen::Vector3d c = b.inertia.com;
  // Parallel-axis theorem about the joint origin, projected on the axis: q-independent.
  const double A = b.axis.dot((b.inertia.inertia + b.inertia.mass * (c.dot(c) * Eigen::Matrix3d::Identity() -
                                                                     c * c.transpose())) *
                              b.axis);
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXd q(1), zero = Eigen::VectorXd::Zero(1), tau(1);
    q[0] = rnd.uniform(-3, 3);
    tau[0] = rnd.uniform(-5, 5);
    sim.set_state(q, zero);
    Eigen::MatrixXd Minv(1, 1);
    sim.inverse_mass_matrix(Minv);
    // Rounding only: 1e-12 relative.
    CHECK_MESSAGE(std::abs(1.0 / Minv(0, 0) - A) < 1e-12 * A, "inertia about the axis: Bullet "
                                                                   << 1.0 / Minv(0, 0) << ", closed form " << A);
    // Gravity torque g = dV/dq = -m a_w . (c_w x gvec), all about the joint origin.
    const Eigen::Matrix3d Rw = b.joint_placement.linear() * Eigen::AngleAxisd(q[0], b.axis).toRotationMatrix();
    const Eigen::Vector3d a_w = b.joint_placement.linear() * b.axis, c_w = Rw * c;
    const double g = -b.inertia.mass * a_w.dot(c_w.cross(m.gravity));
    sim.step(tau);
    const double qdd = sim.qdot()[0] / s.dt;
    // From rest b = 0; Euler's first step is exact up to rounding.
    CHECK_MESSAGE(std::abs(qdd - (tau[0] - g) / A) < 1e-9 * (1.0 + std::abs((tau[0] - g) / A)),
                  "qdd = " << qdd << ", closed form (tau - g)/A = " << (tau[0] - g) / A);
    // The body frame pose is the joint frame rotated about the axis.
    const Eigen::Isometry3d pose = sim.body_pose(0);
    // Compared at the simulated q (the step moved it): rounding of two rotations, 1e-12.
    const Eigen::Matrix3d Rq =
        b.joint_placement.linear() * Eigen::AngleAxisd(sim.q()[0], b.axis).toRotationMatrix();
    CHECK_MESSAGE((pose.linear() - Rq).norm() < 1e-12, "body orientation should be R_J Rot(axis, q)");
    CHECK_MESSAGE((pose.translation() - b.joint_placement.translation()).norm() < 1e-12,
                  "a revolute joint keeps the body origin on the joint origin");
  }
}

TEST_CASE("Link poses follow the state: the arm's tip frame is where the closed form puts it") {
  Simulation sim(two_link_arm());
  opspace::testing::Random rnd(4);
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::Vector2d q = rnd.vector(2, -3, 3);
    sim.set_state(q, Eigen::Vector2d::Zero());
    // Rounding of two rotations: 1e-14 m.
    CHECK_MESSAGE((sim.link_pose("tip").translation() - arm_tip(q)).norm() < 1e-14,
                  "tip at " << sim.link_pose("tip").translation().transpose() << ", closed form "
                            << arm_tip(q).transpose());
  }
  // After steps, the pose is that of the new q, not a stale cache.
  sim.set_state(Eigen::Vector2d(0.3, 0.4), Eigen::Vector2d(1.0, -2.0));
  for (int i = 0; i < 100; ++i) sim.step(Eigen::Vector2d::Zero());
  const Eigen::Vector2d q = sim.q();
  CHECK_MESSAGE((sim.link_pose("tip").translation() - arm_tip(q)).norm() < 1e-14,
                "after 100 steps the tip pose should be that of the simulated q");
}

TEST_CASE("One step advances exactly dt, and 1000 steps make one second") {
  Simulation sim(two_link_arm());
  sim.step(Eigen::Vector2d::Zero());
  CHECK(sim.time() == 1e-3);  // exactly one step of the default dt, not a 1/60 s substep
  for (int i = 1; i < 1000; ++i) sim.step(Eigen::Vector2d::Zero());
  CHECK(sim.time() == doctest::Approx(1.0).epsilon(1e-15));  // time = steps * dt
  CHECK(sim.summary().steps == 1000);
}

TEST_CASE("Torque g(q) holds the arm still, and zero torque conserves its energy") {
  Simulation sim(two_link_arm());
  const Eigen::Vector2d q0(0.4, -0.9);
  sim.set_state(q0, Eigen::Vector2d::Zero());
  for (int i = 0; i < 5000; ++i) sim.step(arm_g(sim.q()));
  // The closed-form g balances Bullet's gravity to rounding; 5 s of 1e-16 errors stay below 1e-9.
  CHECK_MESSAGE((sim.q() - q0).cwiseAbs().maxCoeff() < 1e-9, "drift " << (sim.q() - q0).transpose());

  sim.set_state(q0, Eigen::Vector2d(1.0, -1.5));
  const double e0 = sim.energy().total();
  // Closed-form kinetic energy checks Bullet's energy(): 0.5 qd^T A qd.
  const Eigen::Vector2d qd(1.0, -1.5);
  CHECK(sim.energy().kinetic == doctest::Approx(0.5 * qd.dot(arm_A(q0) * qd)).epsilon(1e-12));
  double worst = 0.0;
  for (int i = 0; i < 5000; ++i) {
    sim.step(Eigen::Vector2d::Zero());
    worst = std::max(worst, std::abs(sim.energy().total() - e0));
  }
  MESSAGE("two-link arm, RK4, 5 s free swing: energy " << e0 << " J, worst drift " << worst << " J");
  // RK4 at 1 ms: error per step O(dt^5); measured 2.9e-8 J of 31 J here (1e-9 relative).
  // Bound: 1e-6 relative, 30x the measurement, far below Euler's percent-level gain.
  CHECK_MESSAGE(worst < 1e-6 * std::abs(e0) + 1e-9, "energy drift " << worst << " J of " << e0 << " J");
}

TEST_CASE("Torques beyond the effort limit are clamped to it and counted per joint") {
  SimulationSettings s;
  s.integrator = Integrator::kEuler;
  Simulation sim(two_link_arm(/*effort1=*/10.0, /*effort2=*/0.0));  // 0: no limit on joint 2
  Simulation ref(two_link_arm(), s);
  Simulation clamped(two_link_arm(10.0, 0.0), s);
  const Eigen::Vector2d q(0.2, 0.3);
  clamped.set_state(q, Eigen::Vector2d::Zero());
  ref.set_state(q, Eigen::Vector2d::Zero());
  clamped.step(Eigen::Vector2d(-25.0, 40.0));
  ref.step(Eigen::Vector2d(-10.0, 40.0));
  CHECK_MESSAGE(clamped.qdot() == ref.qdot(), "-25 N m on a 10 N m joint must act as exactly -10 N m");
  CHECK_MESSAGE(clamped.summary().clamped_steps[0] == 1, "joint 1 was clamped once");
  CHECK_MESSAGE(clamped.summary().clamped_steps[1] == 0, "an effort of 0 means no limit: 40 N m passes");
  CHECK(clamped.summary().max_requested_torque[0] == 25.0);  // the request is reported, not the clamp
  clamped.step(Eigen::Vector2d(9.0, 0.0));
  CHECK_MESSAGE(clamped.summary().total_clamped() == 1, "a torque within the limit is not counted");
}

TEST_CASE("Bad calls are refused with errors that name the sizes and the names") {
  Simulation sim(two_link_arm());
  const auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("(no exception)");
  };
  const std::string wrong_size = message([&] { sim.step(Eigen::VectorXd::Zero(3)); });
  CHECK_MESSAGE(wrong_size.find("3 entries") != std::string::npos, wrong_size);
  CHECK_MESSAGE(wrong_size.find("2 joints") != std::string::npos, wrong_size);
  CHECK_THROWS_AS(sim.step(Eigen::VectorXd::Zero(3)), std::invalid_argument);

  const std::string nan =
      message([&] { sim.step(Eigen::Vector2d(0.0, std::numeric_limits<double>::quiet_NaN())); });
  CHECK_MESSAGE(nan.find("elbow") != std::string::npos, "a NaN torque error names the joint: " << nan);
  CHECK_MESSAGE(nan.find("not a finite") != std::string::npos, nan);
  CHECK(sim.summary().steps == 0);  // a refused call does not step

  const std::string link = message([&] { (void)sim.link_pose("hand"); });
  CHECK_MESSAGE(link.find("'hand'") != std::string::npos, "an unknown link error names it: " << link);
  CHECK_MESSAGE(link.find("tip") != std::string::npos, "and lists the links there are: " << link);
  CHECK_THROWS_AS(sim.contact_wrench("hand"), std::out_of_range);

  const std::string state = message([&] { sim.set_state(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Zero(2)); });
  CHECK_MESSAGE(state.find("joint positions q has 1 entries") != std::string::npos, state);
}

TEST_CASE("A joint spinning beyond the speed bound stops the run with an error naming the joint and the time") {
  SimulationSettings s;
  s.max_joint_speed = 5.0;  // rad/s, low so that a big torque crosses it quickly
  Simulation sim(two_link_arm(), s);
  sim.set_state(Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d::Zero());
  bool thrown = false;
  try {
    for (int i = 0; i < 1000; ++i) sim.step(Eigen::Vector2d(0.0, 50.0));
  } catch (const opspace::SimulationError& e) {
    thrown = true;
    CHECK(e.joint() == "elbow");  // 50 N m on the light forearm: the elbow runs away first
    CHECK(e.time() > 0.0);
    CHECK(e.time() == sim.time());
    const std::string what = e.what();
    CHECK_MESSAGE(what.find("'elbow'") != std::string::npos, what);
    CHECK_MESSAGE(what.find("t = ") != std::string::npos, what);
  }
  CHECK_MESSAGE(thrown, "5 rad/s must be crossed within 1 s at 50 N m");
  CHECK_THROWS_AS(sim.step(Eigen::Vector2d::Zero()), opspace::SimulationError);  // no stepping on
}

namespace {

struct PushResult {
  Eigen::Vector3d force;  // contact force on the forearm, averaged over the last 0.5 s
  Eigen::Vector3d constraint_force;
  Eigen::Vector2d drift;
};

// The arm's tip sphere rests on the plane z = tip_z - r; the arm applies tau = g + J^T F with J
// of the touching point, so at rest the plane pushes back with -F.
PushResult push_on_plane(const Eigen::Vector3d& F, double friction) {
  Simulation sim(two_link_arm());
  const Eigen::Vector2d q0(0.6, 0.9);
  sim.add_plane(Eigen::Vector3d::UnitZ(), arm_tip(q0).z() - kTipRadius, {friction, 0.0});
  sim.set_state(q0, Eigen::Vector2d::Zero());
  PushResult r{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector2d::Zero()};
  const int steps = 2000, averaged = 500;
  for (int i = 0; i < steps; ++i) {
    const Eigen::Vector2d q = sim.q();
    sim.step(arm_g(q) + arm_Jv_contact(q).transpose() * F);
    if (i >= steps - averaged) {
      r.force += sim.contact_wrench("fore").force / averaged;
      const btVector3& f = sim.multibody().getLink(1).m_appliedConstraintForce;
      r.constraint_force += Eigen::Vector3d(f.x(), f.y(), f.z()) / averaged;
    }
  }
  r.drift = sim.q() - q0;
  return r;
}

}  // namespace

TEST_CASE("A tip pressed on a plane with tau = g + J^T F reads back -F through the contact force") {
  // Pure normal push, then a push with a tangential part that friction (mu = 1) must hold.
  for (const Eigen::Vector3d& F : {Eigen::Vector3d(0, 0, -20), Eigen::Vector3d(6, 0, -30)}) {
    const PushResult r = push_on_plane(F, 1.0);
    const double err = (r.force + F).norm() / F.norm();
    MESSAGE("F = " << F.transpose() << ": contact force " << r.force.transpose() << ", relative error " << err
                   << ", drift " << r.drift.transpose());
    // 1%: the bound. Statics makes the reaction exactly -F once the arm is at rest.
    CHECK_MESSAGE(err < 0.01, "contact force " << r.force.transpose() << " should be " << (-F).transpose());
    // Bullet's own per-link sum of the solver's forces is a second reading (bullet-notes: the
    // two agree to 1e-4 N); they add the same impulses, so 1e-9 relative.
    CHECK_MESSAGE((r.constraint_force - r.force).norm() < 1e-9 * F.norm(),
                  "m_appliedConstraintForce " << r.constraint_force.transpose() << " vs manifold sum "
                                              << r.force.transpose());
    CHECK_MESSAGE(r.drift.norm() < 1e-6, "the pressed arm should not move: drift " << r.drift.transpose());
  }
}

TEST_CASE("The same run twice gives bit-identical states and contact forces") {
  const auto run = [] {
    Simulation sim(two_link_arm());
    sim.add_plane(Eigen::Vector3d::UnitZ(), 0.3, {0.8, 0.2});
    sim.add_box(Eigen::Vector3d(0.2, 0.5, 0.2), Eigen::Isometry3d(Eigen::Translation3d(0.6, 0, 0.45)));
    sim.set_state(Eigen::Vector2d(0.1, 0.2), Eigen::Vector2d(2.0, -1.0));
    Eigen::VectorXd trace(3 * 3000);
    for (int i = 0; i < 3000; ++i) {
      sim.step(Eigen::Vector2d(std::sin(0.01 * i), 0.5));
      trace[3 * i] = sim.q()[0];
      trace[3 * i + 1] = sim.qdot()[1];
      trace[3 * i + 2] = sim.contact_wrench(1).force.z();
    }
    return trace;
  };
  const Eigen::VectorXd a = run(), b = run();
  CHECK_MESSAGE((a.array() == b.array()).all(), "two identical runs must agree bit for bit");
  CHECK_MESSAGE(a(Eigen::seqN(2, 3000, 3)).cwiseAbs().maxCoeff() > 0.0,
                "the run should touch an obstacle, or the determinism of contacts is not tested");
}
