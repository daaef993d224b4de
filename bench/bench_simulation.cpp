// Simulated steps per second of the Bullet simulation (1 ms steps, RK4 unless named Euler),
// for the PUMA and the iiwa, in free motion and with a tool pressing on a plane.
// Run: build/<preset>/bench/bench_simulation. Results: docs/performance.md, "## Simulation".
#include <benchmark/benchmark.h>

#include <Eigen/Core>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/model/catalogue.hpp"
#include "opspace/simulation/simulation.hpp"

namespace {

namespace catalogue = opspace::catalogue;

struct Setup {
  opspace::Model model;
  Eigen::VectorXd q0;
  bool contact = false;
};

Setup puma(bool contact) {
  Setup s{catalogue::load(catalogue::kPuma), catalogue::puma_start_q(), contact};  // problem 1b's start
  if (contact) {  // the PUMA has no collider: a 2 cm sphere on its tip point, for this bench
    const opspace::Frame& ee = s.model.frames[s.model.frame_id(catalogue::kPuma.tip_link)];
    opspace::Shape sphere;
    sphere.kind = opspace::Shape::Kind::kSphere;
    sphere.radius = 0.02;
    sphere.body = ee.body;
    sphere.placement = ee.placement * Eigen::Translation3d(catalogue::tip_point(catalogue::kPuma));
    s.model.collisions.push_back(sphere);
  }
  return s;
}

Setup iiwa(bool contact) {
  Setup s{catalogue::load(catalogue::kIiwa), catalogue::iiwa_start_q(), contact};  // problem 2's start
  return s;
}

void run(benchmark::State& state, const Setup& setup, opspace::Integrator integrator) {
  opspace::SimulationSettings settings;
  settings.integrator = integrator;
  opspace::Simulation sim(setup.model, settings);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(setup.model.dof());
  sim.set_state(setup.q0, zero);
  if (setup.contact) {
    // A plane touching the collider (PUMA tip sphere: below; iiwa tool face: along +x). Touching,
    // not penetrating: Bullet pushes a penetration out fast enough to bounce off.
    const auto& shape = setup.model.collisions.back();
    const Eigen::Vector3d centre = (sim.body_pose(shape.body) * shape.placement).translation();
    if (setup.model.name == "iiwa7") {
      sim.add_plane(-Eigen::Vector3d::UnitX(), -(centre.x() + 0.5 * shape.length), {0.5, 0.0});
    } else {
      sim.add_plane(Eigen::Vector3d::UnitZ(), centre.z() - shape.radius, {0.5, 0.0});
    }
  }
  opspace::Data data(setup.model);
  Eigen::VectorXd hold = opspace::generalized_gravity(setup.model, data, setup.q0);
  if (setup.contact) {  // push 10 N into the plane at the collider: tau = g + Jv^T F, at q0
    const auto& shape = setup.model.collisions.back();
    const bool is_iiwa = setup.model.name == "iiwa7";
    const Eigen::Vector3d F = is_iiwa ? Eigen::Vector3d(10, 0, 0) : Eigen::Vector3d(0, 0, -10);
    opspace::Matrix6Xd J(6, setup.model.dof());
    opspace::forward_kinematics(setup.model, data, setup.q0);
    int frame = 0;  // a frame on the collider's body, with the collider's centre as the point
    while (setup.model.frames[frame].body != shape.body) ++frame;
    const Eigen::Vector3d p = setup.model.frames[frame].placement.inverse() * shape.placement.translation();
    opspace::point_jacobian(setup.model, data, frame, p, J);
    hold += J.topRows<3>().transpose() * F;
  }
  Eigen::VectorXd tau = hold;
  long steps = 0, contacts = 0;
  for (auto _ : state) {
    if (steps % 200 == 0) sim.set_state(setup.q0, zero);  // stay near the start (and the plane)
    tau = hold - 5.0 * sim.qdot();                           // gravity and a little damping
    sim.step(tau);
    contacts += static_cast<long>(sim.contacts().size());
    ++steps;
  }
  state.counters["steps_per_s"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
  state.counters["contacts_per_step"] = static_cast<double>(contacts) / static_cast<double>(steps);
}

void BM_Puma_Free(benchmark::State& s) { run(s, puma(false), opspace::Integrator::kRK4); }
void BM_Puma_Contact(benchmark::State& s) { run(s, puma(true), opspace::Integrator::kRK4); }
void BM_Iiwa_Free(benchmark::State& s) { run(s, iiwa(false), opspace::Integrator::kRK4); }
void BM_Iiwa_Contact(benchmark::State& s) { run(s, iiwa(true), opspace::Integrator::kRK4); }
void BM_Iiwa_Free_Euler(benchmark::State& s) { run(s, iiwa(false), opspace::Integrator::kEuler); }
void BM_Iiwa_Contact_Euler(benchmark::State& s) { run(s, iiwa(true), opspace::Integrator::kEuler); }

}  // namespace

BENCHMARK(BM_Puma_Free);
BENCHMARK(BM_Puma_Contact);
BENCHMARK(BM_Iiwa_Free);
BENCHMARK(BM_Iiwa_Contact);
BENCHMARK(BM_Iiwa_Free_Euler);
BENCHMARK(BM_Iiwa_Contact_Euler);
BENCHMARK_MAIN();
