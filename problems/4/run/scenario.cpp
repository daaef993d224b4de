#include <cmath>

#include "opspace/math/constants.hpp"
#include "opspace/simulation/closed_loop.hpp"
#include "opspace/algorithms/dynamics.hpp"
#include <problems/4/run/scenario.hpp>
#include "opspace/simulation/simulation.hpp"
#include "opspace/algorithms/singularity.hpp"
#include "opspace/model/urdf.hpp"
#include "opspace/scenarios/observe.hpp"

namespace opspace::scenarios::p4 {

void Scenario::summarise(Result& result, const Model&, const Simulation&) const {
  const Eigen::Vector3d& x_d = goal_.x_d;
  Summary& s = result.summary;
  if (result.samples.empty()) return;
  for (const Sample& sample : result.samples) {
    add_peak_torque(s, sample.tau);
  }
  s.final_error = (result.samples.back().x - x_d).norm();
  // The first instant after which the error never again exceeds kReachTolerance.
  for (auto it = result.samples.rbegin(); it != result.samples.rend(); ++it) {
    if ((it->x - x_d).norm() > kReachTolerance) break;
    s.reach_time = it->t;
  }
  // A run that stopped early has not stayed at the target.
  if (!result.failure.empty()) s.reach_time = -1.0;
}

std::vector<std::string> Scenario::csv_columns() {
  return {"t", "x", "y", "z", "x_d", "y_d", "z_d", "error", "q1", "q2", "q3", "tau1", "tau2", "tau3"};
}

std::vector<double> Scenario::csv_row(const Sample& s) const {
  const Eigen::Vector3d& x_d = goal_.x_d;
  return {s.t,      s.x(0),   s.x(1),   s.x(2),     x_d(0),     x_d(1),     x_d(2),
          (s.x - x_d).norm(), s.q(0), s.q(1), s.q(2), s.tau(0), s.tau(1), s.tau(2)};
}

Eigen::Vector3d tip_point() { return catalogue::tip_point(catalogue::kRRR); }

Eigen::Vector3d singular_q() { return catalogue::rrr_singular_q(); }

Eigen::Vector3d initial_q(Target target) {
  // q2 = 90 deg - q3 / 2 puts the tip exactly above the base: r = L (cos q2 + cos(q2 + q3)) = 0.
  const double elbow = (target == Target::kAlongZ0 ? 2.0 : 20.0) * kDeg;
  return Eigen::Vector3d(0.0, 90.0 * kDeg - elbow / 2.0, elbow);
}

hw2::p4::Kinematics kinematics(const Model& rrr, Data& data, const Eigen::Ref<const Eigen::Vector3d>& q) {
  const int tip = rrr.frame_id(kTipLink);
  forward_kinematics(rrr, data, q);
  hw2::p4::Kinematics k;
  k.q = q;
  k.x = point_position(rrr, data, tip, tip_point());
  Matrix6Xd J0(6, 3);
  point_jacobian(rrr, data, tip, tip_point(), J0);
  k.Jv = J0.topRows<3>();
  k.Jw = J0.bottomRows<3>();
  Eigen::MatrixXd H(9, 3);
  point_position_hessian(rrr, data, tip, tip_point(), H);
  for (int c = 0; c < 3; ++c) k.H[c] = H.middleRows<3>(3 * c);
  return k;
}

hw2::p4::Goal goal(Target target) {
  static const Model rrr = load_urdf(robot_path(kRobotFile));
  Data data(rrr);
  forward_kinematics(rrr, data, initial_q(target));
  const Eigen::Vector3d x0 = point_position(rrr, data, rrr.frame_id(kTipLink), tip_point());
  hw2::p4::Goal g;
  g.x_d = x0 + (target == Target::kAlongZ0 ? -kTargetDistance * Eigen::Vector3d::UnitZ()
                                           : kTargetDistance * Eigen::Vector3d::UnitY());
  g.kpx = 50.0;
  g.kvx = 20.0;
  g.kpj = 50.0;
  g.kvj = 20.0;
  return g;
}

Observer::Observer(const Model& rrr)
    : model_(require_dof(rrr, 3, "p4::Observer", "problem 4 needs the 3R elbow arm")),
      data_(rrr), robust_(3, rrr.dof()), exact_(3, rrr.dof()), J0_(6, rrr.dof()),
      tip_frame_(rrr.frame_id(kTipLink)) {}

const hw2::p4::State& Observer::observe(double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                                        const Eigen::Ref<const Eigen::VectorXd>& dq) {
  hw2::p4::State& s = state_;
  observe_joints(model_, data_, t, q, dq, s);
  observe_tip(model_, data_, tip_frame_, tip_point(), J0_, s);
  operational_space(s.A, s.Jv, s.g, robust_, kRobustTolerance);
  s.Lambda_v = robust_.Lambda;
  s.Jbar_v = robust_.Jbar;
  s.N = robust_.N;
  s.p = robust_.p;
  operational_space(s.A, s.Jv, s.g, exact_);
  return s;
}

Eigen::Vector3d plain_control(const hw2::p4::State& s, const TaskSpace& exact, const hw2::p4::Goal& goal) {
  // Fixed-size copies of the TaskSpace results, for fixed-size products.
  const Eigen::Matrix3d Lambda = exact.Lambda, N = exact.N;
  const Eigen::Vector3d p = exact.p;
  const Eigen::Vector3d F = Lambda * (-goal.kpx * (s.x - goal.x_d) - goal.kvx * s.dx) + p;
  return s.Jv.transpose() * F + N.transpose() * (s.A * (-goal.kvj * s.dq) + s.g);
}

std::string describe(Target target) {
  return target == Target::kAlongZ0 ? "along Z0 (elbow lock)" : "along Y0 (overhead lock)";
}

Scenario::Scenario(Target target, Law l, std::string name)
    : law(std::move(l)), who(std::move(name)), target_(target), goal_(p4::goal(target)) {}

void Scenario::start(Simulation& sim) const { sim.set_state(initial_q(target_), Eigen::Vector3d::Zero()); }

Sample Scenario::tick(Observer& observer, Simulation& sim, const GainOverrides& gains) const {
  const double t = sim.time();
  const hw2::p4::State& state = observer.observe(t, sim.q(), sim.qdot());
  hw2::p4::Goal g = goal_;
  gains.apply(g);
  const Eigen::Vector3d tau = law(state, observer.exact(), g);
  check_torque(tau, 3, t, who);
  return Sample{t, state.x, state.q, tau};
}

std::string Scenario::what() const { return "problem 4, question v " + describe(target_) + ", " + who; }

Result run(Target target, Controller control, const RunOptions& options) {
  return scenarios::run(
      Scenario(target,
               [control, target](const hw2::p4::State& s, const TaskSpace&, const hw2::p4::Goal& g) {
                 return control(target, s, g);
               },
               "your controller " + describe(target)),
      options);
}

Result run_plain(Target target, const RunOptions& options) {
  return scenarios::run(Scenario(target, &plain_control, "the plain controller"), options);
}

// The graded tests' series (scenario.hpp).
double tip_error(hw2::p4::Target target, const Sample& s) {
  // goal() computes x_d by forward kinematics: once per target, not per sample.
  static const Eigen::Vector3d along_z = goal(hw2::p4::Target::kAlongZ0).x_d;
  static const Eigen::Vector3d along_y = goal(hw2::p4::Target::kAlongY0).x_d;
  return (s.x - (target == hw2::p4::Target::kAlongZ0 ? along_z : along_y)).norm();
}

}  // namespace opspace::scenarios::p4
