// Side-by-side peer: opspace and DART (Debian's libdart) compute A(q), g(q) and b(q, qdot)
// for the same URDF (iiwa7 and PUMA), in one program. Before timing, both libraries are
// compared at a few states; the benchmark aborts if A or g differ beyond 1e-9 relative.
// q changes every iteration: DART caches its dynamics and recomputes them lazily after
// setPositions(), so a loop at a fixed q would time a cache hit. At the end, our time over
// DART's is printed kernel by kernel (ratios of the medians, or of the single runs).
// Built only when CMake finds DART (bench/CMakeLists.txt). Results: docs/performance.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include <dart/dart.hpp>
#include <dart/utils/urdf/urdf.hpp>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/model/catalogue.hpp"
#include "opspace/model/urdf.hpp"

namespace {

using namespace opspace;

/// One robot in both libraries, with a cycle of joint states (in our joint order) to step through.
struct Pair {
  std::string file;
  Model model;
  Data data;
  dart::dynamics::SkeletonPtr skel;
  std::vector<int> dart_index;  ///< DART's DOF index of our joint i
  std::vector<Eigen::VectorXd> q, qdot;            // ours
  std::vector<Eigen::VectorXd> q_dart, qdot_dart;  // the same, in DART's DOF order

  explicit Pair(const std::string& f) : file(f), model(load_urdf(robot_path(f))), data(model) {
    dart::utils::DartLoader::Options options;
    options.mDefaultRootJointType = dart::utils::DartLoader::RootJointType::FIXED;
    dart::utils::DartLoader loader(options);
    skel = loader.parseSkeleton(dart::common::Uri::createFromPath(robot_path(f)));
    if (!skel) fail("DART could not load " + robot_path(f));
    skel->setGravity(model.gravity);
    if (static_cast<int>(skel->getNumDofs()) != model.dof()) {
      fail(f + ": DART has " + std::to_string(skel->getNumDofs()) + " DOFs, opspace " +
           std::to_string(model.dof()));
    }
    for (const Body& body : model.bodies) {
      const dart::dynamics::Joint* joint = skel->getJoint(body.joint_name);
      if (!joint || joint->getNumDofs() != 1) fail(f + ": DART has no 1-DOF joint " + body.joint_name);
      dart_index.push_back(static_cast<int>(joint->getIndexInSkeleton(0)));
    }
    for (int k = 0; k < 64; ++k) {
      q.push_back(Eigen::VectorXd::LinSpaced(model.dof(), -1.0, 1.0) * std::sin(0.1 * k) +
                  Eigen::VectorXd::Constant(model.dof(), 0.2));
      qdot.push_back(Eigen::VectorXd::LinSpaced(model.dof(), 0.5, -0.5) * std::cos(0.1 * k));
      q_dart.push_back(to_dart(q.back()));
      qdot_dart.push_back(to_dart(qdot.back()));
    }
  }

  Eigen::VectorXd to_dart(const Eigen::VectorXd& v) const {
    Eigen::VectorXd r(v.size());
    for (int i = 0; i < model.dof(); ++i) r(dart_index[i]) = v(i);
    return r;
  }
  Eigen::MatrixXd to_dart(const Eigen::MatrixXd& M) const {
    Eigen::MatrixXd r(M.rows(), M.cols());
    for (int i = 0; i < model.dof(); ++i)
      for (int j = 0; j < model.dof(); ++j) r(dart_index[i], dart_index[j]) = M(i, j);
    return r;
  }

  [[noreturn]] static void fail(const std::string& message) {
    std::fprintf(stderr, "bench_dart: %s\n", message.c_str());
    std::exit(EXIT_FAILURE);
  }
};

Pair& pair(int which) {
  static Pair iiwa(catalogue::kIiwa.file);
  static Pair puma(catalogue::kPuma.file);
  return which == 0 ? iiwa : puma;
}

/// max |ours - DART| / max(1, max |DART|) of A, g and b at several states; aborts beyond 1e-9.
void check_agreement(Pair& p) {
  double dA = 0.0, dg = 0.0, db = 0.0;
  for (std::size_t k = 0; k < p.q.size(); k += 9) {
    p.skel->setPositions(p.q_dart[k]);
    p.skel->setVelocities(p.qdot_dart[k]);
    const Eigen::MatrixXd A = p.to_dart(Eigen::MatrixXd(crba(p.model, p.data, p.q[k])));
    const Eigen::VectorXd g = p.to_dart(Eigen::VectorXd(generalized_gravity(p.model, p.data, p.q[k])));
    const Eigen::VectorXd b = p.to_dart(Eigen::VectorXd(coriolis_centrifugal(p.model, p.data, p.q[k], p.qdot[k])));
    const Eigen::MatrixXd& A_dart = p.skel->getMassMatrix();
    const Eigen::VectorXd& g_dart = p.skel->getGravityForces();
    const Eigen::VectorXd& b_dart = p.skel->getCoriolisForces();
    dA = std::max(dA, (A - A_dart).cwiseAbs().maxCoeff() / std::max(1.0, A_dart.cwiseAbs().maxCoeff()));
    dg = std::max(dg, (g - g_dart).cwiseAbs().maxCoeff() / std::max(1.0, g_dart.cwiseAbs().maxCoeff()));
    db = std::max(db, (b - b_dart).cwiseAbs().maxCoeff() / std::max(1.0, b_dart.cwiseAbs().maxCoeff()));
  }
  std::printf("%s: max relative difference opspace - DART over 8 states: A %.1e, g %.1e, b %.1e\n",
              p.model.name.c_str(), dA, dg, db);
  if (!(dA <= 1e-9 && dg <= 1e-9 && db <= 1e-9)) {
    Pair::fail(p.model.name + ": opspace and DART disagree beyond 1e-9 relative; the timings "
               "would compare different computations, so the benchmark stops here");
  }
}

// --- opspace ---

void BM_MassMatrix_opspace(benchmark::State& state) {
  Pair& p = pair(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(crba(p.model, p.data, p.q[k++ % 64]).data());
    benchmark::ClobberMemory();
  }
  state.SetLabel(p.model.name);
}

void BM_Gravity_opspace(benchmark::State& state) {
  Pair& p = pair(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(generalized_gravity(p.model, p.data, p.q[k++ % 64]).data());
    benchmark::ClobberMemory();
  }
  state.SetLabel(p.model.name);
}

void BM_Coriolis_opspace(benchmark::State& state) {
  Pair& p = pair(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t i = k++ % 64;
    benchmark::DoNotOptimize(coriolis_centrifugal(p.model, p.data, p.q[i], p.qdot[i]).data());
    benchmark::ClobberMemory();
  }
  state.SetLabel(p.model.name);
}

// --- DART: the state is set every iteration, so every call recomputes. ---

void BM_MassMatrix_dart(benchmark::State& state) {
  Pair& p = pair(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    p.skel->setPositions(p.q_dart[k++ % 64]);
    benchmark::DoNotOptimize(p.skel->getMassMatrix().data());
    benchmark::ClobberMemory();
  }
  state.SetLabel(p.model.name);
}

void BM_Gravity_dart(benchmark::State& state) {
  Pair& p = pair(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    p.skel->setPositions(p.q_dart[k++ % 64]);
    benchmark::DoNotOptimize(p.skel->getGravityForces().data());
    benchmark::ClobberMemory();
  }
  state.SetLabel(p.model.name);
}

void BM_Coriolis_dart(benchmark::State& state) {
  Pair& p = pair(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t i = k++ % 64;
    p.skel->setPositions(p.q_dart[i]);
    p.skel->setVelocities(p.qdot_dart[i]);
    benchmark::DoNotOptimize(p.skel->getCoriolisForces().data());
    benchmark::ClobberMemory();
  }
  state.SetLabel(p.model.name);
}

// Argument: 0 = iiwa7, 1 = PUMA. Each kernel's two libraries run back to back.
BENCHMARK(BM_MassMatrix_opspace)->Arg(0)->Arg(1);
BENCHMARK(BM_MassMatrix_dart)->Arg(0)->Arg(1);
BENCHMARK(BM_Gravity_opspace)->Arg(0)->Arg(1);
BENCHMARK(BM_Gravity_dart)->Arg(0)->Arg(1);
BENCHMARK(BM_Coriolis_opspace)->Arg(0)->Arg(1);
BENCHMARK(BM_Coriolis_dart)->Arg(0)->Arg(1);

/// Console output as usual, and each run's CPU time per iteration kept (the median when the
/// run is repeated with aggregates) to print opspace / DART at the end.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  RatioReporter() : benchmark::ConsoleReporter(OO_Tabular) {}  // no colour codes in saved logs
  void ReportRuns(const std::vector<Run>& runs) override {
    benchmark::ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.error_occurred) continue;
      const bool aggregate = run.run_type == Run::RT_Aggregate;
      if (aggregate && run.aggregate_name != "median") continue;
      // "BM_MassMatrix_dart/0" -> kernel "BM_MassMatrix", library "dart", robot "0".
      const std::string& fn = run.run_name.function_name;
      const std::size_t cut = fn.rfind('_');
      const std::string kernel = fn.substr(0, cut) + "/" + run.run_name.args;
      const double t = run.GetAdjustedCPUTime();
      (fn.substr(cut + 1) == "dart" ? dart_ : ours_)[kernel] = t;
      label_[kernel] = run.report_label;
    }
  }

  void PrintRatios() const {
    std::printf("\nopspace / DART, CPU time per call (below 1: opspace is faster)\n");
    std::printf("%-22s %-10s %12s %12s %8s\n", "kernel", "robot", "opspace", "DART", "ratio");
    for (const auto& [kernel, ours] : ours_) {
      const auto it = dart_.find(kernel);
      if (it == dart_.end()) continue;
      std::printf("%-22s %-10s %9.0f ns %9.0f ns %8.2f\n", kernel.c_str(), label_.at(kernel).c_str(),
                  ours, it->second, ours / it->second);
    }
  }

 private:
  std::map<std::string, double> ours_, dart_;
  std::map<std::string, std::string> label_;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  check_agreement(pair(0));
  check_agreement(pair(1));
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.PrintRatios();
  benchmark::Shutdown();
  return 0;
}
