// A simulation step allocates nothing from operator new in our code. This program replaces the
// global operator new to count calls, so it is a separate test binary.
//
// What this sees: every operator new (std::vector growth, std::string, make_unique). What it
// does not see: Bullet's own btAlignedAlloc and Eigen's heap temporaries, which call malloc
// directly; the first are Bullet's business, the second are avoided by construction
// (simulation.cpp writes element by element into vectors sized at construction).
#include <doctest/doctest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/simulation/simulation.hpp"
#include "opspace/model/urdf.hpp"

namespace {
std::atomic<long> g_news{0};
}

void* operator new(std::size_t size) {
  ++g_news;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

TEST_CASE("Stepping the iiwa while its tool pushes on a plane calls operator new zero times") {
  const opspace::Model model = opspace::load_urdf(opspace::robot_path("iiwa7.urdf"));
  opspace::Simulation sim(model);
  Eigen::VectorXd q(7);
  q << 2.197, 0.684, -0.859, 1.222, -1.089, 1.400, -3.016;  // problem 2's start (deg -> rad)
  sim.set_state(q, Eigen::VectorXd::Zero(7));
  // The tool face sits near x = 0.05 here: a plane 2 mm behind it makes contact at once.
  const double face_x = sim.link_pose("link7").translation().x() + 0.05;
  sim.add_plane(-Eigen::Vector3d::UnitX(), -(face_x - 0.002), {0.0, 0.0});
  opspace::Data data(model);
  // Problem 3's push: 10 N along +x at link7's origin, on top of gravity compensation. Held
  // open-loop, the arm drifts in its null space and the disc touches in about a third of the
  // steps (measured 338 of 1000): enough to run the contact code under the counter.
  opspace::Matrix6Xd J(6, 7);
  opspace::forward_kinematics(model, data, q);
  opspace::point_jacobian(model, data, model.frame_id("link7"), Eigen::Vector3d::Zero(), J);
  const Eigen::VectorXd tau = opspace::generalized_gravity(model, data, q) +
                              J.topRows<3>().transpose() * Eigen::Vector3d(10.0, 0.0, 0.0);
  for (int i = 0; i < 10; ++i) sim.step(tau);  // warm-up: Bullet sizes its own pools
  size_t touching_steps = 0;
  const long before = g_news.load();
  for (int i = 0; i < 1000; ++i) {
    sim.step(tau);
    touching_steps += sim.contacts().empty() ? 0 : 1;
  }
  const long calls = g_news.load() - before;
  CHECK_MESSAGE(calls == 0, "operator new was called " << calls << " times in 1000 steps");
  CHECK_MESSAGE(touching_steps >= 100, "the tool should touch the plane in many steps, so that "
                                        "contacts are gathered; it did in " << touching_steps);
}

TEST_CASE("Stepping an iiwa with armature while it is pushed calls operator new zero times") {
  // The armature's correction (opspace's forward dynamics at the four RK4 stages, and the
  // push's joint torques) runs in workspaces sized when the simulation is built.
  opspace::Model model = opspace::load_urdf(opspace::robot_path("iiwa7.urdf"));
  for (auto& body : model.bodies) body.armature = 0.5;
  opspace::Simulation sim(model);
  sim.set_state(Eigen::VectorXd::Constant(7, 0.3), Eigen::VectorXd::Zero(7));
  const Eigen::VectorXd tau = Eigen::VectorXd::Zero(7);
  for (int i = 0; i < 10; ++i) sim.step(tau);
  const long before = g_news.load();
  for (int i = 0; i < 1000; ++i) {
    sim.push(6, Eigen::Vector3d(1.0, 0.0, 0.0), sim.body_pose(6).translation());
    sim.step(tau);
  }
  const long calls = g_news.load() - before;
  CHECK_MESSAGE(calls == 0, "operator new was called " << calls << " times in 1000 steps");
}
