/// @file scenarios/summary.hpp
/// What every problem's Summary shares (problems/<key>/run/scenario.hpp derives its Summary from
/// RunTotals): the largest torque the law asked for, which summarise() takes sample by sample,
/// and how far the run got, which the one loop fills (scenarios/loop.hpp).
#pragma once

#include <algorithm>
#include <cmath>

namespace opspace::scenarios {

/// The members of every Summary.
struct RunTotals {
  double peak_torque = 0.0;   ///< max_i |tau_i| requested over the run (N m)
  int peak_torque_joint = 0;  ///< the joint of that maximum (0-based)
  long clamped_steps = 0;     ///< joint-steps whose torque was clamped to an effort limit
  double time_reached = 0.0;  ///< simulated time at the end (s)
};

/// totals.peak_torque = max(peak_torque, max_i |tau_i|), and its joint: one sample's torques, in
/// order (the first joint of a tie keeps it).
template <class Tau>
void add_peak_torque(RunTotals& totals, const Tau& tau) {
  for (int i = 0; i < static_cast<int>(tau.size()); ++i) {
    if (std::abs(tau(i)) > totals.peak_torque) {
      totals.peak_torque = std::abs(tau(i));
      totals.peak_torque_joint = i;
    }
  }
}

/// The largest value and the RMS of an error over part of a run.
struct ErrorStats {
  double max = 0.0;  ///< max_k e_k
  double rms = 0.0;  ///< sqrt(sum_k e_k^2 / n); 0 with no sample
};

/// ErrorStats of e_k = error(sample k) over the samples from time `from` on (t >= from).
template <class Samples, class Error>
ErrorStats error_after(const Samples& samples, double from, Error error) {
  ErrorStats stats;
  double squares = 0.0;
  long n = 0;
  for (const auto& sample : samples) {
    if (sample.t < from) continue;
    const double e = error(sample);
    stats.max = std::max(stats.max, e);
    squares += e * e;
    ++n;
  }
  if (n > 0) stats.rms = std::sqrt(squares / n);
  return stats;
}

}  // namespace opspace::scenarios
