/// @file scenarios/common.hpp
/// What every problem's closed-loop run shares.
#pragma once

#include <iosfwd>
#include <string>

namespace opspace::scenarios {

/// Settings of one closed-loop run.
struct RunOptions {
  double duration = 20.0;                ///< simulated seconds
  std::string csv_path;                  ///< empty: no CSV log
  std::ostream* progress = nullptr;      ///< null: silent
};

}  // namespace opspace::scenarios
