/// @file scenarios/common.hpp
/// What every problem's closed-loop run shares.
#pragma once

#include <cmath>
#include <iosfwd>
#include <limits>
#include <string>
#include <vector>

#include "opspace/scenarios/scenario_check.hpp"

namespace opspace::scenarios {

/// Settings of one closed-loop run.
struct RunOptions {
  double duration = 20.0;                ///< simulated seconds
  std::string csv_path;                  ///< empty: no CSV log
  std::ostream* progress = nullptr;      ///< null: silent
  std::string label = "run";             ///< what the progress lines start with (the program's name)
  /// Wall-clock seconds one step (the controller's tick and the simulation's step) may take
  /// before a Watchdog (scenarios/watchdog.hpp) stops the program; 0: no watchdog.
  double watchdog = 0.0;
};

/// Gains the live lab may change (docs/live.md); NaN: the goal's own.
struct GainOverrides {
  double kpx = std::numeric_limits<double>::quiet_NaN();  ///< task stiffness (1/s^2)
  double kvx = std::numeric_limits<double>::quiet_NaN();  ///< task damping (1/s)
  double kvj = std::numeric_limits<double>::quiet_NaN();  ///< joint damping (1/s)

  /// Sets goal.kpx, kvx, kvj to those overridden.
  template <class Goal>
  void apply(Goal& goal) const {
    static_assert(check::gains<Goal>());
    if (!std::isnan(kpx)) goal.kpx = kpx;
    if (!std::isnan(kvx)) goal.kvx = kvx;
    if (!std::isnan(kvj)) goal.kvj = kvj;
  }
};

/// What a closed-loop run recorded: a problem's Result is RunResult<its Sample, its Summary>.
template <class Sample, class Summary>
struct RunResult {
  std::vector<Sample> samples;  ///< one per 1 ms step
  Summary summary;              ///< what the run measured (the problem's Summary)
  std::string failure;          ///< empty, or what stopped the run early (NaN torque, ...)
};

}  // namespace opspace::scenarios
