// What the programs' --live share (docs/live.md): serve a problem's Lab until Ctrl-C, then
// write the last run's log summary, plots and replay page like any run. Included only where the
// live lab is built (OPSPACE_LIVE).
#pragma once

#include <iostream>
#include <string>

#include "opspace/live/lab.hpp"
#include "opspace/live/run.hpp"

#include "opspace/programs/cli.hpp"

namespace opspace::programs {

/// Serves `lab` live (port, duration from `options`; log at `prefix`-live.csv), then publishes
/// the last run's `figures()` and `scene()` at `prefix`-live-*; returns the exit code.
template <class Lab, class Figures, class Scene>
int serve_live(Lab& lab, const Options& options, const std::string& prefix, Figures figures, Scene scene) {
  opspace::live::LiveOptions live;
  live.port = options.port;
  live.duration = options.duration_given ? options.run.duration : 0.0;
  live.csv_path = prefix + "-live.csv";
  live.watchdog = options.run.watchdog;
  const opspace::live::LiveReport report = opspace::live::serve(lab, live, std::cout);
  std::cout << "\nlive run ended: " << report.steps << " steps in " << report.wall_seconds << " s of wall time, "
            << report.frames << " frames sent, " << report.resyncs << " resynchronisations (a step that fell "
            << live.max_lag << " s behind)\nlog:    " << live.csv_path
            << " (the whole session: pushes, laws, gains and resets as columns)\n";
  if (lab.result().samples.empty()) return 0;
  std::cout << "the pictures below show the last run (since the last reset)\n";
  programs::publish(options, prefix + "-live", figures, scene);
  return 0;
}

}  // namespace opspace::programs
