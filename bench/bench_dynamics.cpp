// Time of the rigid-body algorithms a control tick calls, on the iiwa (7 joints) and the
// PUMA (6 joints): forward kinematics, A(q) by CRBA, g(q), both from one kinematics pass
// (mass_matrix_and_gravity), b(q, qdot) by RNEA, and J0 of the operational point (forward
// kinematics included). q changes every iteration, as in a control loop. The robots and states
// are bench/robots.hpp's, shared with the peers (bench/peer_*): scripts/bench-peers runs this
// program and bench_pinocchio in turns and prints the ratios. Results: docs/performance.md.
#include <benchmark/benchmark.h>

#include <string>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/model/catalogue.hpp"
#include "robots.hpp"

namespace {

using namespace opspace;

/// A robot with its operational point, and the cycle of joint states to step through.
struct Setup {
  Model model;
  Data data;
  int frame;
  Eigen::Vector3d point;
  std::vector<Eigen::VectorXd> q, qdot;

  explicit Setup(const bench::Robot& r)
      : model(catalogue::load(r)),
        data(model),
        frame(model.frame_id(r.tip_link)),
        point(catalogue::tip_point(r)),
        q(bench::positions(model.dof())),
        qdot(bench::velocities(model.dof())) {}
};

/// 0 = iiwa7, 1 = PUMA (bench::kRobots).
Setup& robot(int which) {
  static Setup iiwa(bench::kRobots[0]);
  static Setup puma(bench::kRobots[1]);
  return which == 0 ? iiwa : puma;
}

void label(benchmark::State& state, const Setup& s) { state.SetLabel(s.model.name); }

void BM_MassMatrix(benchmark::State& state) {
  Setup& s = robot(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(crba(s.model, s.data, s.q[k++ % s.q.size()]).data());
    benchmark::ClobberMemory();
  }
  label(state, s);
}

void BM_ForwardKinematics(benchmark::State& state) {
  Setup& s = robot(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    forward_kinematics(s.model, s.data, s.q[k++ % s.q.size()]);
    benchmark::DoNotOptimize(s.data.body_pose.back().data());
    benchmark::ClobberMemory();
  }
  label(state, s);
}

void BM_MassMatrixAndGravity(benchmark::State& state) {
  Setup& s = robot(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    mass_matrix_and_gravity(s.model, s.data, s.q[k++ % s.q.size()]);
    benchmark::DoNotOptimize(s.data.A.data());
    benchmark::DoNotOptimize(s.data.g.data());
    benchmark::ClobberMemory();
  }
  label(state, s);
}

void BM_Gravity(benchmark::State& state) {
  Setup& s = robot(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(generalized_gravity(s.model, s.data, s.q[k++ % s.q.size()]).data());
    benchmark::ClobberMemory();
  }
  label(state, s);
}

void BM_Coriolis(benchmark::State& state) {
  Setup& s = robot(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t i = k++ % s.q.size();
    benchmark::DoNotOptimize(coriolis_centrifugal(s.model, s.data, s.q[i], s.qdot[i]).data());
    benchmark::ClobberMemory();
  }
  label(state, s);
}

void BM_Jacobian(benchmark::State& state) {
  Setup& s = robot(static_cast<int>(state.range(0)));
  Matrix6Xd J0(6, s.model.dof());
  std::size_t k = 0;
  for (auto _ : state) {
    forward_kinematics(s.model, s.data, s.q[k++ % s.q.size()]);
    point_jacobian(s.model, s.data, s.frame, s.point, J0);
    benchmark::DoNotOptimize(J0.data());
    benchmark::ClobberMemory();
  }
  label(state, s);
}

// Argument: 0 = iiwa7, 1 = PUMA.
BENCHMARK(BM_ForwardKinematics)->Arg(0)->Arg(1);
BENCHMARK(BM_MassMatrix)->Arg(0)->Arg(1);
BENCHMARK(BM_Gravity)->Arg(0)->Arg(1);
BENCHMARK(BM_MassMatrixAndGravity)->Arg(0)->Arg(1);
BENCHMARK(BM_Coriolis)->Arg(0)->Arg(1);
BENCHMARK(BM_Jacobian)->Arg(0)->Arg(1);

}  // namespace

BENCHMARK_MAIN();
