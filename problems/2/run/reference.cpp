// Problem 2's reference run (problems/CMakeLists.txt: REFERENCE): solutions/ at hw2-p2's default
// duration, written as reference_runs.hpp's p2() and as the guide's table (fragment p2-reference).
#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <problems/2/contract.hpp>
#include "opspace/model/urdf.hpp"
#include "opspace/programs/reference_text.hpp"
#include <problems/2/run/scenario.hpp>

namespace programs = opspace::programs;

namespace {

namespace p2 = opspace::scenarios::p2;

#define OPSPACE_MEMBER(s, m) set(#m, s.m)
void members(programs::Assignments& set, const p2::Summary& s) {
  OPSPACE_MEMBER(s, position_error_max);
  OPSPACE_MEMBER(s, position_error_rms);
  OPSPACE_MEMBER(s, orientation_error_max);
  OPSPACE_MEMBER(s, orientation_error_rms);
  OPSPACE_MEMBER(s, lambda_norm_error_max);
  OPSPACE_MEMBER(s, lambda_step_max);
  OPSPACE_MEMBER(s, lambda_dot_lambda_d_min);
  OPSPACE_MEMBER(s, joint_limit_margin);
  OPSPACE_MEMBER(s, joint_limit_joint);
  OPSPACE_MEMBER(s, joint_drift_per_period);
  OPSPACE_MEMBER(s, joint_drift_joint);
  programs::run_totals(set, s);
}
#undef OPSPACE_MEMBER

std::string declarations(const p2::Result& r) {
  std::ostringstream out;
  programs::one_run_declarations(out, "2", "2", p2::kDefaultDuration, "opspace::scenarios::p2::Summary", r.summary,
                            &members);
  return out.str();
}

/// The joint closest to (or furthest past) a limit, and when, period by period.
std::string joint_limit_row(const p2::Result& r, const opspace::Body& body) {
  using programs::show;
  const p2::Summary& s = r.summary;
  const int j = s.joint_limit_joint;
  std::ostringstream out;
  out << "| joint " << j + 1 << " | ";
  if (s.joint_limit_margin >= 0.0) {
    out << "stays " << show(s.joint_limit_margin, programs::kDegrees) << " inside its limits |\n";
    return out.str();
  }
  const bool upper =
      std::any_of(r.samples.begin(), r.samples.end(), [&](const p2::Sample& x) { return x.q(j) > body.upper; });
  const double limit = upper ? body.upper : body.lower;
  std::vector<std::string> times;
  for (double start = 0.0; start < s.time_reached; start += p2::kPeriod) {
    double worst = 0.0, when = -1.0;
    for (const p2::Sample& x : r.samples) {
      if (x.t < start || x.t >= start + p2::kPeriod) continue;
      const double past = upper ? x.q(j) - body.upper : body.lower - x.q(j);
      if (past > worst) worst = past, when = x.t;
    }
    if (when >= 0.0) times.push_back(programs::fixed(when, 1) + " s");
  }
  std::string at;
  for (std::size_t i = 0; i < times.size(); ++i) at += (i ? " and " : "") + times[i];
  out << "reaches " << show(upper ? limit - s.joint_limit_margin : limit + s.joint_limit_margin, programs::kDegrees)
      << " at t = " << at << ": **" << show(-s.joint_limit_margin, programs::kDegrees) << " past its "
      << show(limit, programs::kDegrees) << " limit** |\n";
  return out.str();
}

std::string fragment(const p2::Result& r) {
  using programs::max_rms;
  using programs::show;
  const programs::Unit kMrad{"mrad", 1e3};
  const p2::Summary& s = r.summary;
  const opspace::Model iiwa = opspace::load_urdf(opspace::robot_path(p2::kRobotFile));
  std::ostringstream out;
  out << "Measured with `hw2-p2-sol` over " << show(p2::kDefaultDuration, programs::kSeconds)
      << ", the default run and the graded one (errors after the first " << show(p2::kSettleTime, programs::kSeconds)
      << "; the run starts " << show((r.samples.front().x_p - r.samples.front().x_d.head<3>()).norm(), programs::kMm)
      << " from x_d(0)):\n\n"
      << "| quantity | reference |\n|---|---|\n"
      << "| position error | " << max_rms(s.position_error_max, s.position_error_rms, programs::kMm) << " |\n"
      << "| orientation error (angle of R R_d^T) | "
      << max_rms(s.orientation_error_max, s.orientation_error_rms, programs::kDegrees) << " ("
      << max_rms(s.orientation_error_max, s.orientation_error_rms, kMrad) << ") |\n"
      << "| largest change of lambda in one 1 ms step | " << show(s.lambda_step_max, programs::kNone) << " |\n"
      << "| joint drift over the second period | " << show(s.joint_drift_per_period, programs::kDegrees)
      << programs::joint(s.joint_drift_joint) << " |\n"
      << "| peak torque | " << programs::torque(s.peak_torque, s.peak_torque_joint, s.clamped_steps) << " |\n"
      << joint_limit_row(r, iiwa.bodies[static_cast<std::size_t>(s.joint_limit_joint)]);
  return out.str();
}

}  // namespace

programs::ReferenceText reference_run_2() {
  const p2::Result r = programs::reference_result("2", p2::kDefaultDuration,
                                               [](const auto& options) { return p2::run(&opspace::hw2::p2::control, &opspace::hw2::p2::desired_acceleration, options); });
  return {{"problems/2/run/scenario.hpp"}, declarations(r), {{"p2-reference", fragment(r)}}};
}
