// Side-by-side peer: Pinocchio (3.x, header-only or installed) times the kernels of
// bench/bench_dynamics.cpp, under the same benchmark names, on the same robots and states
// (bench/robots.hpp): forward kinematics, A(q) (the full matrix), g(q), A and g, b(q, qdot) and
// the operational point's J0 with its forward kinematics. scripts/bench-peers runs the two
// programs in turns and prints opspace / Pinocchio.
//
// Before timing, the program checks at every timed state that both libraries compute the same
// thing (the last body's pose, A, g, b and J0); it stops with a message if any differs beyond
// kAgreement. Built only when CMake finds Pinocchio (bench/CMakeLists.txt). Results:
// docs/performance.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/frames.hpp>
#include <pinocchio/algorithm/jacobian.hpp>
#include <pinocchio/algorithm/kinematics.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/multibody/data.hpp>
#include <pinocchio/multibody/model.hpp>
#include <pinocchio/parsers/urdf.hpp>

#include "../robots.hpp"
#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/model/catalogue.hpp"

namespace {

namespace pin = pinocchio;

/// Largest difference allowed, relative to max(1, the largest entry): both libraries evaluate
/// the same equations in double precision in a few hundred operations per entry, whose
/// rounding errors (unit roundoff 1.1e-16 each) add up to a few 1e-15 at most; 1e-14 leaves a
/// margin of a few and still flags any real difference (a wrong inertia or axis gives 1e-3 or
/// more).
constexpr double kAgreement = 1e-14;

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "bench_pinocchio: %s\n", message.c_str());
  std::exit(EXIT_FAILURE);
}

/// One robot in both libraries. Pinocchio numbers its joints from 1 (0 is the universe) and
/// orders q by its own traversal: states are mapped by joint name.
struct Pair {
  opspace::Model model;
  opspace::Data data;
  int frame;
  Eigen::Vector3d point;
  pin::Model pmodel;
  pin::Model pmodel_b;  ///< the same without gravity: nonLinearEffects is then b alone
  pin::Data pdata, pdata_b;
  pin::FrameIndex pframe = 0;  ///< an OP_FRAME at the operational point
  std::vector<int> pin_index;  ///< Pinocchio's q index of our joint i
  std::vector<Eigen::VectorXd> q, qdot;            // ours (bench/robots.hpp)
  std::vector<Eigen::VectorXd> q_pin, qdot_pin;    // the same, in Pinocchio's order

  explicit Pair(const opspace::bench::Robot& r)
      : model(opspace::catalogue::load(r)),
        data(model),
        frame(model.frame_id(r.tip_link)),
        point(opspace::catalogue::tip_point(r)),
        q(opspace::bench::positions(model.dof())),
        qdot(opspace::bench::velocities(model.dof())) {
    const std::string path = opspace::catalogue::path(r);
    pin::urdf::buildModel(path, pmodel);  // fixed base
    if (pmodel.nq != model.dof() || pmodel.nv != model.dof()) {
      fail(path + ": Pinocchio has nq " + std::to_string(pmodel.nq) + ", opspace " + std::to_string(model.dof()) +
           " joints");
    }
    for (const opspace::Body& body : model.bodies) {
      if (!pmodel.existJointName(body.joint_name)) fail(path + ": Pinocchio has no joint " + body.joint_name);
      const pin::JointIndex id = pmodel.getJointId(body.joint_name);
      if (pmodel.joints[id].nq() != 1) fail(path + ": Pinocchio's joint " + body.joint_name + " is not 1-DOF");
      pin_index.push_back(pmodel.joints[id].idx_q());
    }
    if (!pmodel.existFrame(r.tip_link, pin::BODY)) fail(path + ": Pinocchio has no body frame " + r.tip_link);
    const pin::Frame& link = pmodel.frames[pmodel.getFrameId(r.tip_link, pin::BODY)];
    pframe = pmodel.addFrame(pin::Frame("operational point", link.parentJoint, pmodel.getFrameId(r.tip_link, pin::BODY),
                                        link.placement * pin::SE3(Eigen::Matrix3d::Identity(), point), pin::OP_FRAME));
    pmodel.gravity.linear(model.gravity);
    pmodel_b = pmodel;
    pmodel_b.gravity.setZero();
    pdata = pin::Data(pmodel);
    pdata_b = pin::Data(pmodel_b);
    for (int k = 0; k < opspace::bench::kStates; ++k) {
      q_pin.push_back(to_pin(q[k]));
      qdot_pin.push_back(to_pin(qdot[k]));
    }
  }

  Eigen::VectorXd to_pin(const Eigen::VectorXd& v) const {
    Eigen::VectorXd r(v.size());
    for (int i = 0; i < model.dof(); ++i) r(pin_index[i]) = v(i);
    return r;
  }
  /// A (n x n): rows and columns mapped.
  Eigen::MatrixXd to_pin_square(const Eigen::MatrixXd& M) const {
    Eigen::MatrixXd r(M.rows(), M.cols());
    for (int i = 0; i < model.dof(); ++i)
      for (int j = 0; j < model.dof(); ++j) r(pin_index[i], pin_index[j]) = M(i, j);
    return r;
  }
  /// J0 (6 x n): columns mapped.
  Eigen::MatrixXd to_pin_columns(const Eigen::MatrixXd& M) const {
    Eigen::MatrixXd r(M.rows(), M.cols());
    for (int j = 0; j < model.dof(); ++j) r.col(pin_index[j]) = M.col(j);
    return r;
  }
};

/// 0 = iiwa7, 1 = PUMA (bench::kRobots).
Pair& pair(int which) {
  static Pair iiwa(opspace::bench::kRobots[0]);
  static Pair puma(opspace::bench::kRobots[1]);
  return which == 0 ? iiwa : puma;
}

/// M's upper triangle (what crba fills) mirrored into its strict lower triangle: the full A.
void mirror_upper(Eigen::MatrixXd& M) {
  M.triangularView<Eigen::StrictlyLower>() = M.transpose().triangularView<Eigen::StrictlyLower>();
}

/// max |ours - Pinocchio's| / max(1, max |Pinocchio's|).
double difference(const Eigen::MatrixXd& ours, const Eigen::MatrixXd& theirs) {
  return (ours - theirs).cwiseAbs().maxCoeff() / std::max(1.0, theirs.cwiseAbs().maxCoeff());
}

/// Compares every quantity timed at every state; stops the program beyond kAgreement.
void check_agreement(Pair& p) {
  double dpose = 0.0, dA = 0.0, dg = 0.0, db = 0.0, dJ = 0.0;
  opspace::Matrix6Xd J0(6, p.model.dof());
  pin::Data::Matrix6x Jpin = pin::Data::Matrix6x::Zero(6, p.pmodel.nv);
  for (int k = 0; k < opspace::bench::kStates; ++k) {
    const Eigen::MatrixXd A = p.to_pin_square(opspace::crba(p.model, p.data, p.q[k]));
    pin::crba(p.pmodel, p.pdata, p.q_pin[k], pin::Convention::LOCAL);
    mirror_upper(p.pdata.M);
    dA = std::max(dA, difference(A, p.pdata.M));
    const Eigen::VectorXd g = p.to_pin(Eigen::VectorXd(opspace::generalized_gravity(p.model, p.data, p.q[k])));
    dg = std::max(dg, difference(g, pin::computeGeneralizedGravity(p.pmodel, p.pdata, p.q_pin[k])));
    const Eigen::VectorXd b =
        p.to_pin(Eigen::VectorXd(opspace::coriolis_centrifugal(p.model, p.data, p.q[k], p.qdot[k])));
    db = std::max(db, difference(b, pin::nonLinearEffects(p.pmodel_b, p.pdata_b, p.q_pin[k], p.qdot_pin[k])));

    // The last body's pose: our body frame is the URDF child link of its joint, Pinocchio's
    // joint frame the same frame (the URDF joint origin).
    opspace::forward_kinematics(p.model, p.data, p.q[k]);
    pin::forwardKinematics(p.pmodel, p.pdata, p.q_pin[k]);
    const pin::SE3& last = p.pdata.oMi[p.pmodel.getJointId(p.model.bodies.back().joint_name)];
    dpose = std::max(dpose, difference(p.data.body_pose.back().matrix().topRows<3>(),
                                       last.toHomogeneousMatrix().topRows<3>()));
    opspace::point_jacobian(p.model, p.data, p.frame, p.point, J0);
    pin::computeFrameJacobian(p.pmodel, p.pdata, p.q_pin[k], p.pframe, pin::LOCAL_WORLD_ALIGNED, Jpin);
    dJ = std::max(dJ, difference(p.to_pin_columns(J0), Jpin));
  }
  std::printf("%s: max difference opspace - Pinocchio over the %d states, relative to max(1, max |entry|): "
              "pose %.1e, A %.1e, g %.1e, b %.1e, J0 %.1e (bound %.0e)\n",
              p.model.name.c_str(), opspace::bench::kStates, dpose, dA, dg, db, dJ, kAgreement);
  if (!(dpose <= kAgreement && dA <= kAgreement && dg <= kAgreement && db <= kAgreement && dJ <= kAgreement)) {
    char bound[16];
    std::snprintf(bound, sizeof bound, "%.0e", kAgreement);
    fail(p.model.name + ": opspace and Pinocchio disagree beyond " + bound +
         "; the timings would compare different computations, so the benchmark stops here");
  }
}

void label(benchmark::State& state, const Pair& p) { state.SetLabel(p.model.name); }

// The same names as bench_dynamics' benchmarks, so that scripts/bench-peers pairs them.

void BM_ForwardKinematics(benchmark::State& state) {
  Pair& p = pair(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    pin::forwardKinematics(p.pmodel, p.pdata, p.q_pin[k++ % p.q_pin.size()]);
    benchmark::DoNotOptimize(p.pdata.oMi.back());
    benchmark::ClobberMemory();
  }
  label(state, p);
}

void BM_MassMatrix(benchmark::State& state) {
  Pair& p = pair(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    pin::crba(p.pmodel, p.pdata, p.q_pin[k++ % p.q_pin.size()], pin::Convention::LOCAL);
    mirror_upper(p.pdata.M);  // opspace's crba returns the full matrix
    benchmark::DoNotOptimize(p.pdata.M.data());
    benchmark::ClobberMemory();
  }
  label(state, p);
}

void BM_Gravity(benchmark::State& state) {
  Pair& p = pair(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(pin::computeGeneralizedGravity(p.pmodel, p.pdata, p.q_pin[k++ % p.q_pin.size()]).data());
    benchmark::ClobberMemory();
  }
  label(state, p);
}

// Pinocchio has no combined call: crba, then computeGeneralizedGravity.
void BM_MassMatrixAndGravity(benchmark::State& state) {
  Pair& p = pair(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    const Eigen::VectorXd& q = p.q_pin[k++ % p.q_pin.size()];
    pin::crba(p.pmodel, p.pdata, q, pin::Convention::LOCAL);
    mirror_upper(p.pdata.M);
    pin::computeGeneralizedGravity(p.pmodel, p.pdata, q);
    benchmark::DoNotOptimize(p.pdata.M.data());
    benchmark::DoNotOptimize(p.pdata.g.data());
    benchmark::ClobberMemory();
  }
  label(state, p);
}

void BM_Coriolis(benchmark::State& state) {
  Pair& p = pair(static_cast<int>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t i = k++ % p.q_pin.size();
    benchmark::DoNotOptimize(pin::nonLinearEffects(p.pmodel_b, p.pdata_b, p.q_pin[i], p.qdot_pin[i]).data());
    benchmark::ClobberMemory();
  }
  label(state, p);
}

void BM_Jacobian(benchmark::State& state) {
  Pair& p = pair(static_cast<int>(state.range(0)));
  pin::Data::Matrix6x J = pin::Data::Matrix6x::Zero(6, p.pmodel.nv);
  std::size_t k = 0;
  for (auto _ : state) {
    pin::computeFrameJacobian(p.pmodel, p.pdata, p.q_pin[k++ % p.q_pin.size()], p.pframe, pin::LOCAL_WORLD_ALIGNED, J);
    benchmark::DoNotOptimize(J.data());
    benchmark::ClobberMemory();
  }
  label(state, p);
}

// Argument: 0 = iiwa7, 1 = PUMA.
BENCHMARK(BM_ForwardKinematics)->Arg(0)->Arg(1);
BENCHMARK(BM_MassMatrix)->Arg(0)->Arg(1);
BENCHMARK(BM_Gravity)->Arg(0)->Arg(1);
BENCHMARK(BM_MassMatrixAndGravity)->Arg(0)->Arg(1);
BENCHMARK(BM_Coriolis)->Arg(0)->Arg(1);
BENCHMARK(BM_Jacobian)->Arg(0)->Arg(1);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  check_agreement(pair(0));
  check_agreement(pair(1));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
