#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "opspace/simulation/closed_loop.hpp"
#include "opspace/algorithms/euler_params.hpp"
#include "opspace/algorithms/linalg.hpp"
#include <problems/3/run/scenario.hpp>
#include "opspace/simulation/simulation.hpp"
#include "opspace/model/urdf.hpp"

namespace opspace::scenarios::p3 {

namespace {

// A push this small is no contact: Bullet reports impulses, a touching contact at rest carries
// the arm's weight share (newtons); 1e-6 N is rounding.
constexpr double kTouching = 1e-6;

// lambda -> lambda (x) q, the Euler parameters of R(lambda) R(q) (Hamilton's product, scalar
// first): linear in lambda, so it maps lambda_d's derivatives too.
Eigen::Matrix4d right_product(const Eigen::Vector4d& q) {
  Eigen::Matrix4d m;
  m << q(0), -q(1), -q(2), -q(3),  //
      q(1), q(0), q(3), -q(2),     //
      q(2), -q(3), q(0), q(1),     //
      q(3), q(2), -q(1), q(0);
  return m;
}

// The probe's tilt of lambda_d: kProbeTilt about link7's own y axis, which lies in the plane.
const Eigen::Matrix4d& probe_tilt() {
  static const Eigen::Matrix4d m = right_product(Eigen::Vector4d(std::cos(kProbeTilt / 2), 0.0, std::sin(kProbeTilt / 2), 0.0));
  return m;
}

}  // namespace

void Scenario::summarise(Result& result, const Model&, const Simulation&) const {
  Summary& s = result.summary;
  double force_error_sum = 0.0, force_sum = 0.0, yz_sq = 0.0, rx_sq = 0.0, tilt_sq = 0.0;
  long n = 0;
  bool touched = false;
  constexpr int kWindow = 10;  // 10 ms moving average of F_x
  double window[kWindow] = {};
  double window_sum = 0.0;
  long index = 0;
  s.x_min = 1e9;
  s.x_max = -1e9;
  for (const Sample& sample : result.samples) {
    add_peak_torque(s, sample.tau);
    const bool pushing = sample.tool_force.x() > kTouching;
    if (pushing && !touched) {
      touched = true;
      s.first_contact_time = sample.t;
    }
    const double fx = sample.tool_force.x();
    window_sum += fx - window[index % kWindow];
    window[index % kWindow] = fx;
    ++index;
    if (sample.t < kSettleTime) continue;
    if (touched && !pushing) ++s.contact_lost_samples;
    s.force_error_max_10ms = std::max(s.force_error_max_10ms, std::abs(window_sum / kWindow - kPushForce));
    const double force_error = std::abs(sample.tool_force.x() - kPushForce);
    const double yz = (sample.x_p.tail<2>() - sample.x_d.segment<2>(1)).norm();
    const double rx = std::abs(sample.rotation_x_error);
    s.force_error_max = std::max(s.force_error_max, force_error);
    s.moment_yz_max = std::max(s.moment_yz_max, sample.tool_moment.tail<2>().norm());
    s.yz_error_max = std::max(s.yz_error_max, yz);
    s.rotation_x_error_max = std::max(s.rotation_x_error_max, rx);
    s.tilt_max = std::max(s.tilt_max, sample.tilt);
    s.x_min = std::min(s.x_min, sample.x_p.x());
    s.x_max = std::max(s.x_max, sample.x_p.x());
    force_error_sum += force_error;
    force_sum += sample.tool_force.x();
    yz_sq += yz * yz;
    rx_sq += rx * rx;
    tilt_sq += sample.tilt * sample.tilt;
    ++n;
  }
  if (n > 0) {
    s.force_error_mean = force_error_sum / n;
    s.force_mean = force_sum / n;
    s.yz_error_rms = std::sqrt(yz_sq / n);
    s.rotation_x_error_rms = std::sqrt(rx_sq / n);
    s.tilt_rms = std::sqrt(tilt_sq / n);
  } else {
    s.x_min = s.x_max = 0.0;
  }
}

std::vector<std::string> Scenario::csv_columns() {
  return {"t",       "x",        "y",        "z",        "l0",       "l1",       "l2",
          "l3",      "y_d",      "z_d",      "l0_d",     "l1_d",     "l2_d",     "l3_d",
          "Fx",      "Fy",       "Fz",       "Mx",       "My",       "Mz",       "contact_points",
          "force_error", "tilt", "rotation_x_error", "q1",  "q2",       "q3",       "q4",
          "q5",      "q6",       "q7",       "tau1",     "tau2",     "tau3",     "tau4",
          "tau5",    "tau6",     "tau7"};
}

std::vector<double> Scenario::csv_row(const Sample& s) const {
  std::vector<double> row = {s.t};
  for (int i = 0; i < 3; ++i) row.push_back(s.x_p(i));
  for (int i = 0; i < 4; ++i) row.push_back(s.lambda(i));
  for (int i = 1; i < 7; ++i) row.push_back(s.x_d(i));
  for (int i = 0; i < 3; ++i) row.push_back(s.tool_force(i));
  for (int i = 0; i < 3; ++i) row.push_back(s.tool_moment(i));
  row.push_back(s.contact_points);
  row.push_back(s.tool_force.x() - kPushForce);
  row.push_back(s.tilt);
  row.push_back(s.rotation_x_error);
  for (int i = 0; i < 7; ++i) row.push_back(s.q(i));
  for (int i = 0; i < 7; ++i) row.push_back(s.tau(i));
  return row;
}

Vector7d initial_q() {
  // Newton steps q <- q - J0^+ [x_p - x_pd(0); delta_phi] from problem 2's start (5 mm and
  // under a degree from the pose) converge quadratically: three reach round-off.
  static const Vector7d q0 = [] {
    const Model iiwa = load_urdf(robot_path(kRobotFile));
    Observer observer(iiwa);
    const Vector7d x_d = p2::desired(0.0).x;  // the problem set's pose, without goal()'s probes
    Vector7d q = p2::initial_q();
    for (int iteration = 0; iteration < 20; ++iteration) {
      const hw2::p3::State& s = observer.observe(0.0, q, Vector7d::Zero(), x_d.tail<4>());
      Vector6d error;
      error << s.x_p - x_d.head<3>(), orientation_error(s.lambda, x_d.tail<4>());
      if (error.norm() < 1e-14) return q;
      q -= pseudo_inverse(s.J0) * error;
    }
    throw std::logic_error("p3::initial_q: the Newton steps onto the desired pose at t = 0 did not converge");
  }();
  return q0;
}

hw2::p3::Goal goal(double t) {
  const p2::Reference r = p2::desired(t);
  hw2::p3::Goal g;
  g.x_d = r.x;
  g.xdot_d = r.xdot;
  g.xddot_d = r.xddot;
  // The force-controlled directions' probes, which the law's Omega removes: x_d along x moves
  // through the plane (kProbeAmplitude), lambda_d is tilted off it (kProbeTilt).
  const double w = 2.0 * kPi / kPeriod;
  g.x_d(0) = kProbeAmplitude * std::sin(w * t);
  g.xdot_d(0) = kProbeAmplitude * w * std::cos(w * t);
  g.xddot_d(0) = -kProbeAmplitude * w * w * std::sin(w * t);
  g.x_d.tail<4>() = probe_tilt() * r.x.tail<4>();
  g.xdot_d.tail<4>() = probe_tilt() * r.xdot.tail<4>();
  g.xddot_d.tail<4>() = probe_tilt() * r.xddot.tail<4>();
  g.F_d << kPushForce, 0, 0, 0, 0, 0;
  g.kpx = 50.0;
  g.kvx = 20.0;
  g.kvj = 20.0;
  return g;
}

void Scenario::start(Simulation& sim) {
  // The half-space x >= 0.05, i.e. -x <= -0.05: its surface faces the robot (normal -x).
  sim.add_plane(-Eigen::Vector3d::UnitX(), -kPlaneX, Material{0.0, 0.0});
  sim.set_state(initial_q(), Vector7d::Zero());
  tool_body_ = sim.link_body(kTipLink);
}

Sample Scenario::tick(Observer& observer, Simulation& sim, const GainOverrides& gains) const {
  const double t = sim.time();
  hw2::p3::Goal g = goal(t);
  gains.apply(g);
  const hw2::p3::State& state = observer.observe(t, sim.q(), sim.qdot(), g.x_d.tail<4>());
  const Vector7d tau = control_(state, g);
  check_torque(tau, 7, t, "your controller");
  Sample sample;
  sample.t = t;
  sample.x_p = state.x_p;
  sample.lambda = state.lambda;
  const Vector7d x_d = p2::desired(t).x;  // what the tests judge: the problem set's, without the probes
  sample.x_d = x_d;
  const Wrench& w = sim.contact_wrench(tool_body_);
  sample.tool_force = -w.force;
  sample.tool_moment = -w.moment;
  for (const Contact& c : sim.contacts()) sample.contact_points += c.body == tool_body_ ? 1 : 0;
  const Eigen::Vector3d tool_axis = rotation_matrix(state.lambda).col(2);
  sample.tilt = std::atan2(tool_axis.cross(Eigen::Vector3d::UnitX()).norm(), tool_axis.x());
  sample.rotation_x_error = orientation_error(state.lambda, x_d.tail<4>()).x();
  sample.q = state.q;
  sample.tau = tau;
  return sample;
}

Result run(Controller control, const RunOptions& options) {
  return scenarios::run(Scenario(std::move(control)), options);
}

// The graded tests' series (scenario.hpp).
double force_error(const Sample& s) { return std::abs(s.tool_force.x() - kPushForce); }
double tilt_angle(const Sample& s) { return s.tilt; }
double yz_error(const Sample& s) { return (s.x_p.tail<2>() - s.x_d.segment<2>(1)).norm(); }
double rotation_x_error(const Sample& s) { return std::abs(s.rotation_x_error); }
double push(const Sample& s) { return s.tool_force.x(); }

}  // namespace opspace::scenarios::p3
