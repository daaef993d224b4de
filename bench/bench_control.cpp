// Time of one whole control tick, as the reference controllers compute it every 1 ms:
// the library's State (kinematics, A, g, Lambda, Jbar, p) plus the law (solutions/), for
// problems 1b (PUMA), 2 (iiwa, full law), 3 (iiwa, motion and force) and 4 (RRR); and of the operational-space kernels
// a tick is made of: the Cholesky (LLT) and LDLT solves of A, and operational_space()
// (Lambda, Jbar, N, p) for the iiwa's 6-D task and the PUMA's 3-D task.
// q changes every iteration, as in a control loop. Results: docs/performance.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/algorithms/opspace.hpp"
#include "opspace/model/catalogue.hpp"
#include <problems/1b/run/scenario.hpp>
#include <problems/2/run/scenario.hpp>
#include <problems/3/run/scenario.hpp>
#include <problems/4/run/scenario.hpp>

namespace {

namespace p1b = opspace::scenarios::p1b;
using opspace::hw2::p1b::Part;

struct P1bSetup {
  opspace::Model puma = opspace::catalogue::load(opspace::catalogue::kPuma);
  p1b::Observer observer{puma};
  std::vector<p1b::Vector6d> q, dq;
  P1bSetup() {
    for (int k = 0; k < 64; ++k) {
      q.push_back(p1b::initial_q() + p1b::Vector6d::Constant(0.3 * std::sin(0.1 * k)));
      dq.push_back(p1b::Vector6d::LinSpaced(0.5, -0.5) * std::cos(0.1 * k));
    }
  }
};

P1bSetup& p1b_setup() {
  static P1bSetup setup;
  return setup;
}

void BM_P1bState(benchmark::State& state) {
  P1bSetup& s = p1b_setup();
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(s.observer.observe(0.001 * k, s.q[k % 64], s.dq[k % 64]));
    ++k;
  }
}
BENCHMARK(BM_P1bState);

void BM_P1bTick(benchmark::State& state) {
  P1bSetup& s = p1b_setup();
  const Part part = static_cast<Part>(state.range(0));
  std::size_t k = 0;
  for (auto _ : state) {
    const opspace::hw2::p1b::State& st = s.observer.observe(0.001 * k, s.q[k % 64], s.dq[k % 64]);
    benchmark::DoNotOptimize(opspace::hw2::p1b::control(part, st, p1b::goal(st.t, st.q)));
    ++k;
  }
}
BENCHMARK(BM_P1bTick)->Arg(1)->Arg(2)->Arg(3)->ArgName("part");

// --- Problem 2: the iiwa's 6-D task, the full law (position and Euler parameters). ---

namespace p2 = opspace::scenarios::p2;

struct P2Setup {
  opspace::Model iiwa = opspace::catalogue::load(opspace::catalogue::kIiwa);
  p2::Observer observer{iiwa};
  std::vector<p2::Vector7d> q, dq;
  P2Setup() {
    for (int k = 0; k < 64; ++k) {
      q.push_back(p2::initial_q() + p2::Vector7d::Constant(0.3 * std::sin(0.1 * k)));
      dq.push_back(p2::Vector7d::LinSpaced(0.5, -0.5) * std::cos(0.1 * k));
    }
  }
};

P2Setup& p2_setup() {
  static P2Setup setup;
  return setup;
}

void BM_P2State(benchmark::State& state) {
  P2Setup& s = p2_setup();
  const p2::Reference ref = p2::desired(0.5);
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(s.observer.observe(0.001 * k, s.q[k % 64], s.dq[k % 64], ref.x.tail<4>()));
    ++k;
  }
}
BENCHMARK(BM_P2State);

// Everything p2::run() does in one step besides simulating, in its order: the goal (the
// reference x_d(t) and its rate), the desired acceleration, the State and the law. (Until issue
// 21 this loop computed the reference twice, once more than run() does: about 6% of the tick.)
void BM_P2Tick(benchmark::State& state) {
  P2Setup& s = p2_setup();
  std::size_t k = 0;
  for (auto _ : state) {
    const double t = 0.001 * static_cast<double>(k % 5000);
    opspace::hw2::p2::Goal goal = p2::goal(t);
    goal.xddot_d = opspace::hw2::p2::desired_acceleration(t);
    const opspace::hw2::p2::State& st = s.observer.observe(t, s.q[k % 64], s.dq[k % 64], goal.x_d.tail<4>());
    benchmark::DoNotOptimize(opspace::hw2::p2::control(st, goal));
    ++k;
  }
}
BENCHMARK(BM_P2Tick);

// --- Problem 3: the same State, the unified motion and force law against the plane. ---

// Everything p3::run() does in one step besides simulating: the goal, the State and the law.
void BM_P3Tick(benchmark::State& state) {
  P2Setup& s = p2_setup();
  std::size_t k = 0;
  for (auto _ : state) {
    const double t = 0.001 * static_cast<double>(k % 5000);
    const opspace::hw2::p3::Goal goal = opspace::scenarios::p3::goal(t);
    const opspace::hw2::p3::State& st = s.observer.observe(t, s.q[k % 64], s.dq[k % 64], goal.x_d.tail<4>());
    benchmark::DoNotOptimize(opspace::hw2::p3::control(st, goal));
    ++k;
  }
}
BENCHMARK(BM_P3Tick);

// --- Problem 4: the RRR arm near its singularity, robust and exact task quantities. ---

namespace p4 = opspace::scenarios::p4;
using opspace::hw2::p4::Target;

struct P4Setup {
  opspace::Model rrr = opspace::catalogue::load(opspace::catalogue::kRRR);
  p4::Observer observer{rrr};
  std::vector<Eigen::Vector3d> q[2], dq;
  P4Setup() {
    for (int k = 0; k < 64; ++k) {
      for (const Target target : {Target::kAlongZ0, Target::kAlongY0}) {
        q[static_cast<int>(target) - 1].push_back(p4::initial_q(target) + Eigen::Vector3d::Constant(0.05 * std::sin(0.1 * k)));
      }
      dq.push_back(Eigen::Vector3d(0.1, -0.2, 0.3) * std::cos(0.1 * k));
    }
  }
};

P4Setup& p4_setup() {
  static P4Setup setup;
  return setup;
}

void BM_P4Tick(benchmark::State& state) {
  P4Setup& s = p4_setup();
  const Target target = static_cast<Target>(state.range(0));
  const opspace::hw2::p4::Goal goal = p4::goal(target);
  const std::vector<Eigen::Vector3d>& q = s.q[static_cast<int>(target) - 1];
  std::size_t k = 0;
  for (auto _ : state) {
    const opspace::hw2::p4::State& st = s.observer.observe(0.001 * k, q[k % 64], s.dq[k % 64]);
    benchmark::DoNotOptimize(opspace::hw2::p4::control(target, st, goal));
    ++k;
  }
}
BENCHMARK(BM_P4Tick)->Arg(static_cast<int>(Target::kAlongZ0))->Arg(static_cast<int>(Target::kAlongY0))->ArgName("target");

// --- Kernels: solves of A and operational_space(), on precomputed A, J, g. ---

/// A(q), g(q) and J (the first task_dim rows of the tip's J0) at 64 states of a robot.
struct KernelSetup {
  std::string name;
  std::vector<opspace::JointMatrix> A;
  std::vector<Eigen::MatrixXd> J;
  std::vector<Eigen::VectorXd> g;
  Eigen::Index dof = 0, task_dim = 0;

  KernelSetup(const opspace::catalogue::CourseRobot& robot, Eigen::Index m) : task_dim(m) {
    const opspace::Model model = opspace::catalogue::load(robot);
    const Eigen::Vector3d point = opspace::catalogue::tip_point(robot);
    opspace::Data data(model);
    name = model.name;
    dof = model.dof();
    const int frame = model.frame_id(robot.tip_link);
    opspace::Matrix6Xd J0(6, dof);
    for (int k = 0; k < 64; ++k) {
      const Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(dof, -1.0, 1.0) * std::sin(0.1 * k) +
                                Eigen::VectorXd::Constant(dof, 0.3);
      A.push_back(opspace::crba(model, data, q));
      g.push_back(opspace::generalized_gravity(model, data, q));
      opspace::forward_kinematics(model, data, q);
      opspace::point_jacobian(model, data, frame, point, J0);
      J.push_back(J0.topRows(m));
    }
  }
};

/// 0: the iiwa's 6-D task (problem 2: link7's origin), 1: the PUMA's 3-D task (problem 1b's tip).
KernelSetup& kernel_setup(int which) {
  static KernelSetup iiwa(opspace::catalogue::kIiwa, 6);
  static KernelSetup puma(opspace::catalogue::kPuma, 3);
  return which == 0 ? iiwa : puma;
}

void BM_SolveLLT(benchmark::State& state) {
  KernelSetup& s = kernel_setup(static_cast<int>(state.range(0)));
  Eigen::LLT<opspace::JointMatrix> llt(s.dof);
  Eigen::VectorXd x(s.dof);
  std::size_t k = 0;
  for (auto _ : state) {
    llt.compute(s.A[k % 64]);
    x = s.g[k % 64];
    llt.solveInPlace(x);
    benchmark::DoNotOptimize(x.data());
    benchmark::ClobberMemory();
    ++k;
  }
  state.SetLabel(s.name);
}
BENCHMARK(BM_SolveLLT)->Arg(0)->Arg(1);

void BM_SolveLDLT(benchmark::State& state) {
  KernelSetup& s = kernel_setup(static_cast<int>(state.range(0)));
  Eigen::LDLT<opspace::JointMatrix> ldlt(s.dof);
  Eigen::VectorXd x(s.dof);
  std::size_t k = 0;
  for (auto _ : state) {
    ldlt.compute(s.A[k % 64]);
    x = s.g[k % 64];
    ldlt.solveInPlace(x);
    benchmark::DoNotOptimize(x.data());
    benchmark::ClobberMemory();
    ++k;
  }
  state.SetLabel(s.name);
}
BENCHMARK(BM_SolveLDLT)->Arg(0)->Arg(1);

void BM_OperationalSpace(benchmark::State& state) {
  KernelSetup& s = kernel_setup(static_cast<int>(state.range(0)));
  opspace::TaskSpace task(s.task_dim, s.dof);
  std::size_t k = 0;
  for (auto _ : state) {
    opspace::operational_space(s.A[k % 64], s.J[k % 64], s.g[k % 64], task);
    benchmark::DoNotOptimize(task.N.data());
    benchmark::ClobberMemory();
    ++k;
  }
  state.SetLabel(s.name + (s.task_dim == 6 ? ", 6-D task" : ", 3-D task"));
}
BENCHMARK(BM_OperationalSpace)->Arg(0)->Arg(1);

}  // namespace

BENCHMARK_MAIN();
