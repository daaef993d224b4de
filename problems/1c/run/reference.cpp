// Problem 1c's reference run (problems/CMakeLists.txt: REFERENCE): solutions/ at hw2-p1c's
// default duration, written as reference_runs.hpp's p1c() and as the guide's table (fragment
// p1c-reference).
#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>

#include <opspace/hw2/p1c.hpp>
#include <opspace/programs/reference_text.hpp>
#include <problems/1c/run/scenario.hpp>

namespace {

namespace p1b = opspace::scenarios::p1b;
namespace p1c = opspace::scenarios::p1c;

#define OPSPACE_MEMBER(s, m) set(#m, s.m)
void members(cli::Assignments& set, const p1b::Summary& s) {
  OPSPACE_MEMBER(s, tip_error_max);
  OPSPACE_MEMBER(s, tip_error_rms);
  OPSPACE_MEMBER(s, q2_error_max);
  OPSPACE_MEMBER(s, q2_error_rms);
  OPSPACE_MEMBER(s, peak_torque);
  OPSPACE_MEMBER(s, peak_torque_joint);
  OPSPACE_MEMBER(s, clamped_steps);
  OPSPACE_MEMBER(s, time_reached);
}
#undef OPSPACE_MEMBER

std::string declarations(const p1c::Result& r) {
  std::ostringstream out;
  out << "/// Simulated seconds of problem 1c's reference run.\n"
      << "inline constexpr double kP1cDuration = " << p1b::kDefaultDuration << ";\n\n"
      << "/// solutions/' run of problem 1c.\n";
  cli::summary_function<p1b::Summary>(out, "p1c()", "opspace::scenarios::p1b::Summary", {{"", r.summary}}, &members);
  return out.str();
}

/// The largest joint speed of the run from 1 ms differences of q (rad/s).
double largest_speed(const p1c::Result& r) {
  double speed = 0.0;
  for (std::size_t k = 1; k < r.samples.size(); ++k) {
    const double dt = r.samples[k].t - r.samples[k - 1].t;
    speed = std::max(speed, (r.samples[k].q - r.samples[k - 1].q).cwiseAbs().maxCoeff() / dt);
  }
  return speed;
}

std::string fragment(const p1c::Result& r) {
  using cli::show;
  const p1b::Summary& s = r.summary;
  std::ostringstream out;
  out << "Measured with `hw2-p1c-sol` over " << show(p1b::kDefaultDuration, cli::kSeconds)
      << " (errors after the first " << show(p1b::kSettleTime, cli::kSeconds) << "):\n\n"
      << "| quantity | reference |\n|---|---|\n"
      << "| tip error | " << cli::max_rms(s.tip_error_max, s.tip_error_rms, cli::kMm) << " |\n"
      << "| fastest joint | " << show(largest_speed(r), {"rad/s", 1.0}) << " |\n"
      << "| peak torque | " << cli::torque(s.peak_torque, s.peak_torque_joint, s.clamped_steps) << " |\n";
  return out.str();
}

}  // namespace

cli::ReferenceText reference_run_1c() {
  opspace::scenarios::RunOptions options;
  options.duration = p1b::kDefaultDuration;
  const p1c::Result r = p1c::run(&opspace::hw2::p1c::control, options);
  if (!r.failure.empty()) throw std::runtime_error("problem 1c's reference run stopped early: " + r.failure);
  return {{"problems/1c/run/scenario.hpp"}, declarations(r), {{"p1c-reference", fragment(r)}}};
}
