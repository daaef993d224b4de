// A push with the mouse: the spring's law, the effective mass, and the force's way into the
// simulation (lib/src/live/push.cpp, Simulation::push).
#include <doctest/doctest.h>

#include <cmath>

#include "opspace/algorithms/kinematics.hpp"
#include "opspace/live/push.hpp"
#include "opspace/math/constants.hpp"
#include <problems/1b/run/scenario.hpp>
#include "opspace/simulation/simulation.hpp"
#include "opspace/model/urdf.hpp"

using namespace opspace;

TEST_CASE("the spring pulls with m (w^2 dx - 2 zeta w v), and no harder than its maximum") {
  const live::Spring spring;  // f = 1 Hz, zeta = 1, 50 N
  const double w = 2.0 * kPi;
  // Closed form at rest, 1 cm short of the mouse, 2 kg: 2 (2 pi)^2 0.01 = 0.79 N toward it.
  const Eigen::Vector3d F = live::spring_force(spring, 2.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                               Eigen::Vector3d(0.01, 0.0, 0.0));
  CHECK(F.x() == doctest::Approx(2.0 * w * w * 0.01).epsilon(1e-12));
  CHECK(F.tail<2>().norm() == 0.0);
  // Moving toward the mouse at 0.1 m/s, the damper takes 2 zeta w m v off.
  const Eigen::Vector3d Fd = live::spring_force(spring, 2.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.01, 0.0, 0.0),
                                                Eigen::Vector3d(0.01, 0.0, 0.0));
  CHECK(Fd.x() == doctest::Approx(2.0 * (w * w * 0.01 - 2.0 * w * 0.01)).epsilon(1e-12));
  // 10 m away the spring would pull with 2 (2 pi)^2 10 = 790 N: clamped to 50 N, same direction.
  const Eigen::Vector3d far = live::spring_force(spring, 2.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                                 Eigen::Vector3d(6.0, 8.0, 0.0));
  CHECK_MESSAGE(far.norm() == doctest::Approx(spring.max_force).epsilon(1e-12), "the clamp bounds |F|");
  CHECK_MESSAGE(far.normalized().isApprox(Eigen::Vector3d(0.6, 0.8, 0.0), 1e-12), "the clamp keeps the direction");
}

TEST_CASE("the effective mass is 3 / trace(Jv A^-1 Jv^T)") {
  // Two joints moving the point along x and y, with masses 2 and 4 (A diagonal):
  // trace = 1/2 + 1/4 = 3/4, so m = 4 kg.
  Eigen::MatrixXd Jv = Eigen::MatrixXd::Zero(3, 2);
  Jv(0, 0) = 1.0;
  Jv(1, 1) = 1.0;
  const Eigen::MatrixXd A = Eigen::Vector2d(2.0, 4.0).asDiagonal();
  CHECK(live::effective_mass(Jv, A) == doctest::Approx(4.0).epsilon(1e-14));
  CHECK_MESSAGE(std::isinf(live::effective_mass(Eigen::MatrixXd::Zero(3, 2), A)),
                "a point no joint moves cannot be pushed: infinite mass, which the clamp bounds");
}

TEST_CASE("a push on a link moves the arm as the joint torques Jv^T F do, for one step only") {
  // Virtual work: a force F at point p does the work of the joint torques Jv(p)^T F, so a
  // push and those torques give the same step, to rounding. The PUMA from problem 1b's start.
  // Euler steps: the identity holds at the step's start pose, where both are evaluated; RK4's
  // inner stages would move the world-fixed force and the joint torques apart by O(dt^2).
  const Model puma = load_urdf(robot_path("puma.urdf"));
  const Eigen::VectorXd q0 = scenarios::p1b::initial_q(), zero = Eigen::VectorXd::Zero(6);
  SimulationSettings euler;
  euler.integrator = Integrator::kEuler;
  Simulation pushed(puma, euler), torqued(puma, euler), free(puma, euler);
  for (Simulation* s : {&pushed, &torqued, &free}) s->set_state(q0, zero);

  const int elbow = puma.joint_id("elbow");  // body 2 carries lower_arm
  const Eigen::Vector3d local(0.1, 0.05, 0.0), F(20.0, -10.0, 30.0);
  Data data(puma);
  forward_kinematics(puma, data, q0);
  const int frame = puma.frame_id(puma.bodies[elbow].link_name);
  Matrix6Xd J0(6, 6);
  point_jacobian(puma, data, frame, local, J0);
  const Eigen::VectorXd tau = J0.topRows<3>().transpose() * F;

  pushed.push(elbow, F, point_position(puma, data, frame, local));
  pushed.step(zero);
  torqued.step(tau);
  free.step(zero);
  CHECK_MESSAGE((pushed.qdot() - torqued.qdot()).norm() < 1e-9 * torqued.qdot().norm(),
                "push: " << pushed.qdot().transpose() << "\nJv^T F: " << torqued.qdot().transpose());
  CHECK_MESSAGE((pushed.qdot() - free.qdot()).norm() > 1e-3, "the push moved the arm");
  // The next step without a push: the force is gone (Bullet clears it with the joint torques).
  pushed.step(zero);
  torqued.step(zero);
  CHECK((pushed.qdot() - torqued.qdot()).norm() < 1e-9 * torqued.qdot().norm());
  CHECK_MESSAGE(pushed.summary().total_clamped() == 0, "a push is no joint torque: nothing clamped or counted");
}

TEST_CASE("a push on a body the robot does not have, or with a NaN, is refused") {
  const Model puma = load_urdf(robot_path("puma.urdf"));
  Simulation sim(puma);
  CHECK_THROWS_AS(sim.push(6, Eigen::Vector3d::UnitX(), Eigen::Vector3d::Zero()), std::out_of_range);
  CHECK_THROWS_AS(sim.push(1, Eigen::Vector3d(NAN, 0, 0), Eigen::Vector3d::Zero()), std::invalid_argument);
}
