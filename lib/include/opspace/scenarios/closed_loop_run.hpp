/// @file scenarios/closed_loop_run.hpp
/// The closed loop every problem's run() shares: tick, record, log, step until the duration.
#pragma once

#include <cmath>
#include <cstddef>
#include <exception>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "opspace/simulation/closed_loop.hpp"
#include "opspace/scenarios/common.hpp"
#include "opspace/scenarios/watchdog.hpp"
#include "opspace/simulation/simulation.hpp"

namespace opspace::scenarios {

/// Runs `sim` from its current state for options.duration seconds and returns what it recorded.
/// At each step, `tick(t)` computes and checks the torques and returns the Sample of time t
/// (with its `tau`); the loop appends it to Result::samples, writes `csv_row(sample)` to the
/// CSV log with `columns` (if options.csv_path is set), reports progress as `label` and applies
/// `tau` for one step (not after the last sample). An exception ends the run early with its
/// message in Result::failure; Result::summary gets time_reached and clamped_steps. With
/// options.watchdog, a step that takes longer than that stops the program with a message
/// naming `what` (e.g. "problem 1b, PART3").
template <class Result, class Tick, class CsvRow>
Result run_closed_loop(Simulation& sim, const std::string& label, const std::string& what,
                       const std::vector<std::string>& columns, const RunOptions& options, Tick tick,
                       CsvRow csv_row) {
  const long steps = std::lround(options.duration / sim.settings().dt);
  Result result;
  result.samples.reserve(static_cast<std::size_t>(steps) + 1);
  Progress progress(options.progress ? *options.progress : std::clog, label, options.duration);
  std::unique_ptr<CsvLog> csv;
  if (!options.csv_path.empty()) csv = std::make_unique<CsvLog>(options.csv_path, columns);
  Watchdog watchdog(options.watchdog, what);

  try {
    for (long k = 0; k <= steps; ++k) {
      const double t = sim.time();
      watchdog.beat(t);
      result.samples.push_back(tick(t));
      if (csv) csv->row(csv_row(result.samples.back()));
      if (options.progress) progress.update(t);
      if (k < steps) sim.step(result.samples.back().tau);
    }
  } catch (const std::exception& e) {
    result.failure = e.what();
  }
  if (options.progress) progress.finish();
  result.summary.time_reached = sim.time();
  result.summary.clamped_steps = sim.summary().total_clamped();
  return result;
}

}  // namespace opspace::scenarios
