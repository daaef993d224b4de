// Time of one whole control tick, as the reference controllers compute it every 1 ms:
// the library's State (kinematics, A, g, Lambda, Jbar, p) plus the law (solutions/).
// q changes every iteration, as in a control loop. Results: docs/performance.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "opspace/scenarios.hpp"
#include "opspace/urdf.hpp"

namespace {

namespace p1b = opspace::scenarios::p1b;
using opspace::hw2::p1b::Part;

struct P1bSetup {
  opspace::Model puma = opspace::load_urdf(opspace::robot_path(p1b::kRobotFile));
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

}  // namespace

BENCHMARK_MAIN();
