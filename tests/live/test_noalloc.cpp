// What the live lab adds to each step allocates nothing on the heap once its workspaces exist:
// the push's force (lib/src/live/push.cpp) and problem 1b's prediction of its offset
// (problems/1b/run/lab.cpp, offset.cpp). The only file of test_live that counts allocations.
#include <doctest/doctest.h>

#include <problems/1b/contract.hpp>
#include <problems/1b/run/lab.hpp>
#include "opspace/live/push.hpp"
#include "support/count_allocations.hpp"

using namespace opspace;
using hw2::p1b::Part;

// Seen to fail: with p1b_static_tip_offset factoring A as an Eigen::MatrixXd, 2 allocations.
TEST_CASE("the page's prediction of a push's offset allocates nothing in the control tick") {
  live::P1bLab lab("hw2-p1", Part::kDynamicallyConsistentNullspace, &hw2::p1b::control);
  lab.tick();
  const Eigen::VectorXd torque = Eigen::VectorXd::LinSpaced(6, 10.0, -5.0);  // any Je^T F (N m)
  const long n = allocations_in([&] { lab.set_push_torque(torque); });
  CHECK_MESSAGE(n == 0, "the prediction allocated ", n, " times");
  CHECK(lab.predicted_offset().norm() > 0.0);
}

// Seen to fail: before the Pusher kept its factorisation of A and L^-1 Jv^T as workspaces, 2
// allocations per step of a push.
TEST_CASE("a push's force and joint torques allocate nothing per step") {
  live::P1bLab lab("hw2-p1", Part::kDynamicallyConsistentNullspace, &hw2::p1b::control);
  const Simulation& sim = lab.simulation();
  live::Pusher pusher(sim.model());
  const live::Spring spring;
  const Eigen::Vector3d target(0.0, 0.5, 1.5);
  pusher.force(spring, sim.q(), sim.qdot(), 2, Eigen::Vector3d::Zero(), target);  // as a Session's first step
  live::PushForce push;
  const long n = allocations_in([&] { push = pusher.force(spring, sim.q(), sim.qdot(), 2, Eigen::Vector3d::Zero(), target); });
  CHECK_MESSAGE(n == 0, "one push step allocated ", n, " times");
  CHECK(push.force.norm() > 0.0);
  CHECK(pusher.joint_torque().norm() > 0.0);
}
