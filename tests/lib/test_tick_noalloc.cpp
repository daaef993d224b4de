// A whole control tick allocates nothing on the heap: the library computes the controller's
// State (kinematics, A, g, Lambda, Jbar, p) and the reference law turns it into torques,
// with fixed-size matrices and workspaces sized once, for problems 1b, 2, 3 and 4. (Linked with
// solutions/.)
#include <doctest/doctest.h>

#include <utility>

#include "opspace/algorithms/opspace.hpp"
#include <problems/1b/run/scenario.hpp>
#include <problems/2/run/scenario.hpp>
#include <problems/3/run/scenario.hpp>
#include <problems/4/run/scenario.hpp>
#include "opspace/model/urdf.hpp"
#include "support/count_allocations.hpp"

using opspace::hw2::p1b::Part;

TEST_CASE("a problem-1b control tick allocates nothing once its workspaces exist") {
  namespace p1b = opspace::scenarios::p1b;
  const opspace::Model puma = opspace::load_urdf(opspace::robot_path(p1b::kRobotFile));
  p1b::Observer observer(puma);
  const p1b::Vector6d q = p1b::initial_q();
  const p1b::Vector6d dq = p1b::Vector6d::LinSpaced(0.3, -0.2);
  p1b::Vector6d sink = p1b::Vector6d::Zero();
  observer.observe(0.0, q, dq);  // warm-up: nothing is lazily sized, but measure a steady tick
  for (const Part part : {Part::kTipPd, Part::kTipPdWithoutJointDamping, Part::kPseudoInverseNullspace,
                          Part::kDynamicallyConsistentNullspace}) {
    CAPTURE(static_cast<int>(part));
    const long n = allocations_in([&] {
      const opspace::hw2::p1b::State& s = observer.observe(0.5, q, dq);
      sink += opspace::hw2::p1b::control(part, s, p1b::goal(0.5, s.q));
    });
    CHECK_MESSAGE(n == 0, "one tick allocated ", n, " times");
  }
  CHECK(sink.allFinite());
}

TEST_CASE("a problem-2 control tick allocates nothing once its workspaces exist") {
  namespace p2 = opspace::scenarios::p2;
  const opspace::Model iiwa = opspace::load_urdf(opspace::robot_path("iiwa7.urdf"));
  p2::Observer observer(iiwa);
  const p2::Vector7d q = p2::initial_q();
  const p2::Vector7d dq = p2::Vector7d::LinSpaced(0.3, -0.2);
  p2::Vector7d sink = p2::Vector7d::Zero();
  const long n = allocations_in([&] {
    const p2::Reference ref = p2::desired(0.5);
    const opspace::hw2::p2::State& s = observer.observe(0.5, q, dq, ref.x.tail<4>());
    opspace::hw2::p2::Goal goal = p2::goal(0.5);
    goal.xddot_d = opspace::hw2::p2::desired_acceleration(0.5);
    sink += opspace::hw2::p2::control(s, goal);
  });
  CHECK_MESSAGE(n == 0, "one tick allocated ", n, " times");
  CHECK(sink.allFinite());
}

TEST_CASE("a problem-3 control tick allocates nothing once its workspaces exist") {
  namespace p3 = opspace::scenarios::p3;
  const opspace::Model iiwa = opspace::load_urdf(opspace::robot_path(p3::kRobotFile));
  p3::Observer observer(iiwa);
  const p3::Vector7d q = p3::initial_q();
  const p3::Vector7d dq = p3::Vector7d::LinSpaced(0.3, -0.2);
  p3::Vector7d sink = p3::Vector7d::Zero();
  const long n = allocations_in([&] {
    const opspace::hw2::p3::Goal goal = p3::goal(0.5);
    const opspace::hw2::p3::State& s = observer.observe(0.5, q, dq, goal.x_d.tail<4>());
    sink += opspace::hw2::p3::control(s, goal);
  });
  CHECK_MESSAGE(n == 0, "one tick allocated ", n, " times");
  CHECK(sink.allFinite());
}

TEST_CASE("a problem-4 control tick allocates nothing once its workspaces exist") {
  namespace p4 = opspace::scenarios::p4;
  const opspace::Model rrr = opspace::load_urdf(opspace::robot_path(p4::kRobotFile));
  p4::Observer observer(rrr);
  Eigen::Vector3d sink = Eigen::Vector3d::Zero();
  for (const p4::Target target : {p4::Target::kAlongZ0, p4::Target::kAlongY0}) {
    const Eigen::Vector3d q = p4::initial_q(target);
    const Eigen::Vector3d dq(0.1, -0.2, 0.3);
    const opspace::hw2::p4::Goal goal = p4::goal(target);
    const long n = allocations_in([&] {
      const opspace::hw2::p4::State& s = observer.observe(0.5, q, dq);
      sink += opspace::hw2::p4::control(target, s, goal);
      sink += p4::plain_control(s, observer.exact(), goal);
    });
    CHECK_MESSAGE(n == 0, "one tick allocated ", n, " times");
  }
  CHECK(sink.allFinite());
}

TEST_CASE("operational_space allocates nothing at any size, on either inversion path") {
  // The ticks above run the kernels compiled for their shapes and, away from singularities,
  // the Cholesky path. Other shapes run the same code with run-time sizes, and a singular
  // task the eigen-decomposition: neither may reach for the heap.
  for (const auto& [m, n] : {std::pair<int, int>{2, 7}, {6, 12}, {3, 6}}) {
    CAPTURE(m);
    CAPTURE(n);
    const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(n, n) * 2.0;
    Eigen::MatrixXd J = Eigen::MatrixXd::Identity(m, n);
    const Eigen::VectorXd g = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
    opspace::TaskSpace task(m, n);
    const long regular = allocations_in([&] { opspace::operational_space(A, J, g, task); });
    CHECK(task.rank == m);
    CHECK_MESSAGE(regular == 0, "operational_space allocated ", regular, " times on the Cholesky path");
    J.row(m - 1) = J.row(0);  // two equal rows: J A^-1 J^T is singular
    const long singular = allocations_in([&] { opspace::operational_space(A, J, g, task); });
    CHECK(task.rank == m - 1);  // the eigen path ran: one direction dropped
    CHECK_MESSAGE(singular == 0, "operational_space allocated ", singular, " times on the eigen path");
  }
}
