/// @file scenarios/common.hpp
/// What every problem's closed-loop run shares.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace opspace::scenarios {

/// Settings of one closed-loop run.
struct RunOptions {
  double duration = 20.0;                ///< simulated seconds
  std::string csv_path;                  ///< empty: no CSV log
  std::ostream* progress = nullptr;      ///< null: silent
  /// Wall-clock seconds one step (the controller's tick and the simulation's step) may take
  /// before a Watchdog (scenarios/watchdog.hpp) stops the program; 0: no watchdog.
  double watchdog = 0.0;
};

/// What a closed-loop run recorded: a problem's Result is RunResult<its Sample, its Summary>.
template <class Sample, class Summary>
struct RunResult {
  std::vector<Sample> samples;  ///< one per 1 ms step
  Summary summary;              ///< what the run measured (the problem's Summary)
  std::string failure;          ///< empty, or what stopped the run early (NaN torque, ...)
};

}  // namespace opspace::scenarios
