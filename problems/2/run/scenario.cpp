#include <algorithm>
#include <cmath>
#include <limits>

#include "opspace/math/constants.hpp"
#include "opspace/simulation/closed_loop.hpp"
#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/euler_params.hpp"
#include <problems/2/run/scenario.hpp>
#include "opspace/simulation/simulation.hpp"
#include "opspace/scenarios/observe.hpp"

namespace opspace::scenarios::p2 {

void Scenario::summarise(Result& result, const Model& iiwa, const Simulation& sim) const {
  const double dt = sim.settings().dt;
  Summary& s = result.summary;
  double position_sq = 0.0, orientation_sq = 0.0;
  long n = 0;
  s.joint_limit_margin = std::numeric_limits<double>::infinity();
  const Sample* previous = nullptr;
  for (const Sample& sample : result.samples) {
    add_peak_torque(s, sample.tau);
    for (int i = 0; i < 7; ++i) {
      const Body& body = iiwa.bodies[static_cast<std::size_t>(i)];
      const double margin = std::min(sample.q(i) - body.lower, body.upper - sample.q(i));
      if (margin < s.joint_limit_margin) {
        s.joint_limit_margin = margin;
        s.joint_limit_joint = i;
      }
    }
    const Eigen::Vector4d lambda_d = sample.x_d.tail<4>();
    s.lambda_norm_error_max = std::max(s.lambda_norm_error_max, std::abs(sample.lambda.norm() - 1.0));
    s.lambda_dot_lambda_d_min = std::min(s.lambda_dot_lambda_d_min, sample.lambda.dot(lambda_d));
    if (previous) s.lambda_step_max = std::max(s.lambda_step_max, (sample.lambda - previous->lambda).norm());
    previous = &sample;
    if (sample.t < kSettleTime) continue;
    const double position = (sample.x_p - sample.x_d.head<3>()).norm();
    const double orientation = rotation_angle_between(sample.lambda, lambda_d);
    s.position_error_max = std::max(s.position_error_max, position);
    s.orientation_error_max = std::max(s.orientation_error_max, orientation);
    position_sq += position * position;
    orientation_sq += orientation * orientation;
    ++n;
  }
  if (n > 0) {
    s.position_error_rms = std::sqrt(position_sq / n);
    s.orientation_error_rms = std::sqrt(orientation_sq / n);
  }
  if (result.samples.empty()) s.joint_limit_margin = 0.0;
  const auto per_period = static_cast<std::size_t>(std::lround(kPeriod / dt));
  if (!result.samples.empty() && result.samples.back().t >= kSettleTime + kPeriod &&
      result.samples.size() > per_period) {
    const Sample& last = result.samples.back();
    const Sample& before = result.samples[result.samples.size() - 1 - per_period];
    s.joint_drift_per_period = (last.q - before.q).cwiseAbs().maxCoeff(&s.joint_drift_joint);
  }
}

std::vector<std::string> Scenario::csv_columns() {
  return {"t",    "x",    "y",    "z",    "l0",   "l1",   "l2",   "l3",   "x_d",  "y_d",
          "z_d",  "l0_d", "l1_d", "l2_d", "l3_d", "position_error", "orientation_error",
          "q1",   "q2",   "q3",   "q4",   "q5",   "q6",   "q7",   "tau1", "tau2", "tau3",
          "tau4", "tau5", "tau6", "tau7"};
}

std::vector<double> Scenario::csv_row(const Sample& s) const {
  std::vector<double> row = {s.t};
  for (int i = 0; i < 3; ++i) row.push_back(s.x_p(i));
  for (int i = 0; i < 4; ++i) row.push_back(s.lambda(i));
  for (int i = 0; i < 7; ++i) row.push_back(s.x_d(i));
  row.push_back((s.x_p - s.x_d.head<3>()).norm());
  row.push_back(rotation_angle_between(s.lambda, s.x_d.tail<4>()));
  for (int i = 0; i < 7; ++i) row.push_back(s.q(i));
  for (int i = 0; i < 7; ++i) row.push_back(s.tau(i));
  return row;
}

Vector7d initial_q() { return catalogue::iiwa_start_q(); }

Reference desired(double t) {
  const double w = 2.0 * kPi / 5.0;
  const double s = 1.0 / std::sqrt(2.0);
  const double c1 = std::cos(w * t), s1 = std::sin(w * t);
  const double c2 = std::cos(2.0 * w * t), s2 = std::sin(2.0 * w * t);
  // a = (pi/4) cos(w t) and its derivatives
  const double a = kPi / 4.0 * c1, a_dot = -kPi / 4.0 * w * s1, a_ddot = -kPi / 4.0 * w * w * c1;
  const double sa = std::sin(a), ca = std::cos(a);
  Reference r;
  r.x << 0.0, 0.5 + 0.1 * c1, 0.65 - 0.05 * c2, s * sa, s * ca, s * sa, s * ca;
  r.xdot << 0.0, -0.1 * w * s1, 0.1 * w * s2, s * ca * a_dot, -s * sa * a_dot, s * ca * a_dot, -s * sa * a_dot;
  // d2/dt2 sin(a) = cos(a) a'' - sin(a) a'^2,  d2/dt2 cos(a) = -sin(a) a'' - cos(a) a'^2
  const double sin_a_ddot = ca * a_ddot - sa * a_dot * a_dot;
  const double cos_a_ddot = -sa * a_ddot - ca * a_dot * a_dot;
  r.xddot << 0.0, -0.1 * w * w * c1, 0.2 * w * w * c2, s * sin_a_ddot, s * cos_a_ddot, s * sin_a_ddot,
      s * cos_a_ddot;
  return r;
}

hw2::p2::Goal goal(double t) {
  const Reference r = desired(t);
  hw2::p2::Goal g;
  g.x_d = r.x;
  g.xdot_d = r.xdot;
  g.xddot_d.setZero();
  g.kpx = 50.0;
  g.kvx = 20.0;
  g.kvj = 20.0;
  return g;
}

Observer::Observer(const Model& iiwa)
    : model_(require_dof(iiwa, 7, "p2::Observer", "problem 2 needs the 7-joint iiwa")),
      data_(iiwa), task_(6, iiwa.dof()), J0_(6, iiwa.dof()), tip_frame_(iiwa.frame_id(kTipLink)) {}

const hw2::p2::State& Observer::observe(double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                                        const Eigen::Ref<const Eigen::VectorXd>& dq,
                                        const Eigen::Ref<const Eigen::Vector4d>& lambda_side) {
  hw2::p2::State& s = state_;
  observe_joints(model_, data_, t, q, dq, s);  // also the forward kinematics of q, used below
  const Eigen::Isometry3d pose = frame_pose(model_, data_, tip_frame_);
  s.x_p = pose.translation();
  s.lambda = same_side(euler_parameters(pose.linear()), lambda_side);
  point_jacobian(model_, data_, tip_frame_, Eigen::Vector3d::Zero(), J0_);
  s.J0 = J0_;
  const Vector6d twist = s.J0 * s.dq;
  s.v = twist.head<3>();
  s.w = twist.tail<3>();
  operational_space(s.A, s.J0, s.g, task_);
  s.Lambda0 = task_.Lambda;
  s.Jbar0 = task_.Jbar;
  s.N0 = task_.N;
  s.p = task_.p;
  return s;
}

void Scenario::start(Simulation& sim) const { sim.set_state(initial_q(), Vector7d::Zero()); }

Sample Scenario::tick(Observer& observer, Simulation& sim, const GainOverrides& gains) const {
  const double t = sim.time();
  hw2::p2::Goal g = goal(t);
  gains.apply(g);
  g.xddot_d = desired_acceleration(t);
  if (!g.xddot_d.allFinite()) {
    throw ControllerError("your desired_acceleration (2a) returned a value that is not finite at t = " +
                              std::to_string(t) + " s",
                          t);
  }
  const hw2::p2::State& state = observer.observe(t, sim.q(), sim.qdot(), g.x_d.tail<4>());
  const Vector7d tau = control(state, g);
  check_torque(tau, 7, t, "your controller");
  return Sample{t, state.x_p, state.lambda, g.x_d, state.q, tau};
}

Result run(Controller control, DesiredAcceleration desired_acceleration, const RunOptions& options) {
  return scenarios::run(Scenario{std::move(control), std::move(desired_acceleration)}, options);
}

// The graded tests' series (scenario.hpp).
double position_error(const Sample& s) { return (s.x_p - s.x_d.head<3>()).norm(); }
double orientation_angle(const Sample& s) { return rotation_angle_between(s.lambda, s.x_d.tail<4>()); }
double lambda_dot_lambda_d(const Sample& s) { return s.lambda.dot(s.x_d.tail<4>()); }

}  // namespace opspace::scenarios::p2
