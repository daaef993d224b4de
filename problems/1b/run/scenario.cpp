#include <cmath>

#include "opspace/math/constants.hpp"
#include "opspace/simulation/closed_loop.hpp"
#include "opspace/algorithms/dynamics.hpp"
#include <problems/1b/run/scenario.hpp>
#include "opspace/simulation/simulation.hpp"

namespace opspace::scenarios::p1b {

void Scenario::summarise(Result& result, const Model&, const Simulation&) const {
  Summary& s = result.summary;
  for (const Sample& sample : result.samples) add_peak_torque(s, sample.tau);
  const Eigen::Vector3d& x_d = x_d_;
  const ErrorStats tip = error_after(result.samples, kSettleTime, [&x_d](const Sample& x) { return (x.x - x_d).norm(); });
  const ErrorStats q2 = error_after(result.samples, kSettleTime, &q2_error);
  s.tip_error_max = tip.max, s.tip_error_rms = tip.rms;
  s.q2_error_max = q2.max, s.q2_error_rms = q2.rms;
}

std::vector<std::string> Scenario::csv_columns() {
  return {"t",    "x",    "y",    "z",    "x_d",  "y_d",  "z_d",  "tip_error", "q1",   "q2",
          "q3",   "q4",   "q5",   "q6",   "q2_d", "tau1", "tau2", "tau3",      "tau4", "tau5",
          "tau6"};
}

std::vector<double> Scenario::csv_row(const Sample& s) const {
  const Eigen::Vector3d& x_d = x_d_;
  std::vector<double> row = {s.t, s.x(0), s.x(1), s.x(2), x_d(0), x_d(1), x_d(2), (s.x - x_d).norm()};
  for (int i = 0; i < 6; ++i) row.push_back(s.q(i));
  row.push_back(s.q2_desired);
  for (int i = 0; i < 6; ++i) row.push_back(s.tau(i));
  return row;
}

namespace {

std::string who(hw2::p1b::Part part) {
  return "your " + describe(part).substr(0, describe(part).find(':')) + " controller";
}

}  // namespace

SimulationSettings Scenario::settings() {
  // PART2's law spins the light wrist (its links weigh 0.1-0.8 kg and the model, like Bullet,
  // has no motor inertia) to a few hundred rad/s: that wild motion is the lesson, so the run
  // must not stop below kMaxJointSpeed.
  SimulationSettings settings;
  settings.max_joint_speed = kMaxJointSpeed;
  return settings;
}

Eigen::Vector3d tip_point() { return catalogue::tip_point(catalogue::kPuma); }

Vector6d initial_q() { return catalogue::puma_start_q(); }

double desired_q2(double t) { return -kPi / 8.0 + kPi / 8.0 * std::sin(2.0 * kPi * t / 10.0); }

hw2::p1b::Goal goal(double t, const Eigen::Ref<const Vector6d>& q) {
  hw2::p1b::Goal g;
  g.x_d = Eigen::Vector3d(-0.15, 0.81, 0.58);
  g.q_d = q;
  g.q_d(1) = desired_q2(t);
  g.kpx = 50.0;
  g.kvx = 20.0;
  g.kpj = 50.0;
  g.kvj = 20.0;
  return g;
}

Observer::Observer(const Model& puma)
    : PointTaskObserver(puma, 6, kTipLink, tip_point(), "p1b::Observer", "problem 1b needs the 6-joint PUMA") {}

std::string describe(hw2::p1b::Part part) {
  switch (part) {
    case hw2::p1b::Part::kTipPd: return "PART1: tip PD with joint damping";
    case hw2::p1b::Part::kPseudoInverseNullspace: return "PART2: null-space task with the pseudo-inverse projector";
    case hw2::p1b::Part::kDynamicallyConsistentNullspace:
      return "PART3: null-space task with the dynamically consistent projector";
    case hw2::p1b::Part::kTipPdWithoutJointDamping: return "PART1 without joint damping";
  }
  return "unknown part";
}

Scenario::Scenario(hw2::p1b::Part law, Controller control)
    : part(law), control_(std::move(control)), x_d_(goal(0.0, initial_q()).x_d), named_part_(law), who_(who(law)) {}

void Scenario::start(Simulation& sim) const { sim.set_state(initial_q(), Vector6d::Zero()); }

Sample Scenario::tick(Observer& observer, Simulation& sim, const GainOverrides& gains) {
  const double t = sim.time();
  const hw2::p1b::State& state = observer.observe(t, sim.q(), sim.qdot());
  hw2::p1b::Goal g = goal(t, state.q);
  gains.apply(g);
  const Vector6d tau = control_(part, state, g);
  if (part != named_part_) {  // the live lab switched laws
    named_part_ = part;
    who_ = who(part);
  }
  check_torque(tau, 6, t, who_);
  return Sample{t, state.x, state.q, g.q_d(1), tau};
}

std::string Scenario::what() const { return "problem 1b, " + describe(part); }

Result run(hw2::p1b::Part part, Controller control, const RunOptions& options) {
  return scenarios::run(Scenario(part, std::move(control)), options);
}

// The graded tests' series (scenario.hpp).
double tip_error(const Sample& s) {
  static const Eigen::Vector3d x_d = goal(0.0, initial_q()).x_d;  // fixed in this scenario
  return (s.x - x_d).norm();
}
double q2_error(const Sample& s) { return std::abs(s.q(1) - s.q2_desired); }

}  // namespace opspace::scenarios::p1b
