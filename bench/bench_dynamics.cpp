// Time of the rigid-body algorithms a control tick calls, on the iiwa (7 joints) and the
// PUMA (6 joints): forward kinematics, A(q) by CRBA, g(q), both from one kinematics pass
// (mass_matrix_and_gravity), b(q, qdot) by RNEA, and J0 of the operational point (forward
// kinematics included). q changes every iteration, as in a control loop.
// Results: docs/performance.md.
#include <benchmark/benchmark.h>

#include <string>

#include "opspace/dynamics.hpp"
#include "opspace/kinematics.hpp"
#include "opspace/urdf.hpp"

namespace {

using namespace opspace;

/// A robot with its operational point, and a cycle of joint states to step through.
struct Setup {
  Model model;
  Data data;
  int frame;
  Eigen::Vector3d point;
  std::vector<Eigen::VectorXd> q, qdot;

  Setup(const std::string& file, const std::string& frame_name, const Eigen::Vector3d& p)
      : model(load_urdf(robot_path(file))), data(model), frame(model.frame_id(frame_name)), point(p) {
    for (int k = 0; k < 64; ++k) {
      q.push_back(Eigen::VectorXd::LinSpaced(model.dof(), -1.0, 1.0) * std::sin(0.1 * k));
      qdot.push_back(Eigen::VectorXd::LinSpaced(model.dof(), 0.5, -0.5) * std::cos(0.1 * k));
    }
  }
};

/// The operational points of problems 2 (iiwa link7 origin) and 1b (PUMA tip).
Setup& robot(int which) {
  static Setup iiwa("iiwa7.urdf", "link7", Eigen::Vector3d::Zero());
  static Setup puma("puma.urdf", "end-effector", Eigen::Vector3d(-0.2, 0, 0));
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
