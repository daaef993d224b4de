/// @file scenarios/loop.hpp
/// The one closed loop of every problem. A problem describes its scenario once, as a class
/// (`p<key>::Scenario`, in problems/<key>/run/scenario.hpp); Loop<Scenario> runs it one tick at a
/// time (the live lab's loop) and run(scenario, options) for a duration (the programs', the
/// graded tests' and the reference's runs).
///
/// A Scenario S has
///   S::Observer, S::Sample, S::Summary   the State from (t, q, dq), one instant, what a run measured
///   S::kRobotFile                       the URDF of robots/ that builds the Model and the simulation
///   S::settings()                       the simulation's settings
///   s.start(sim)                        the start: q(0), dq(0) = 0, the scene's obstacles
///   s.tick(observer, sim, gains)        the instant t = sim.time(): State, Goal (with the live lab's
///                                       gains), tau = the law's, checked; the Sample with its tau
///   s.what()                            the run's name in the watchdog's message ("problem 2")
///   s.csv_columns(), s.csv_row(sample)  the CSV log
///   s.summarise(result, model, sim)     the Summary of a finished run
///   S::kGradedDuration                  simulated seconds of a graded run and of a --test replay
/// and its Sample has `t` and `tau`, its Summary `time_reached` and `clamped_steps` (derived from
/// RunTotals, scenarios/summary.hpp). Loop<S> checks them at compile time (scenario_check.hpp).
#pragma once

#include <cmath>
#include <cstddef>
#include <exception>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "opspace/model/model.hpp"
#include "opspace/model/urdf.hpp"
#include "opspace/scenarios/common.hpp"
#include "opspace/scenarios/scenario_check.hpp"
#include "opspace/scenarios/summary.hpp"
#include "opspace/scenarios/watchdog.hpp"
#include "opspace/simulation/closed_loop.hpp"
#include "opspace/simulation/simulation.hpp"

namespace opspace::scenarios {

/// Runs `sim` from its current state for options.duration seconds and returns what it recorded.
/// At each step, `tick(t)` computes and checks the torques and returns the Sample of time t
/// (with its `tau`); the loop appends it to Result::samples, writes `csv_row(sample)` to the
/// CSV log with `columns` (if options.csv_path is set), reports progress as options.label and
/// applies `tau` for one step (not after the last sample). An exception ends the run early with
/// its message in Result::failure; Result::summary gets time_reached and clamped_steps. With
/// options.watchdog, a step that takes longer than that stops the program with a message
/// naming `what` (e.g. "problem 1b, PART3").
template <class Result, class Tick, class CsvRow>
Result run_closed_loop(Simulation& sim, const std::string& what, const std::vector<std::string>& columns,
                       const RunOptions& options, Tick tick, CsvRow csv_row) {
  const long steps = std::lround(options.duration / sim.settings().dt);
  Result result;
  result.samples.reserve(static_cast<std::size_t>(steps) + 1);
  Progress progress(options.progress ? *options.progress : std::clog, options.label, options.duration);
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

/// A problem's closed loop one tick at a time: the robot of Scenario::kRobotFile read once, its
/// Observer, its simulation at the scenario's start (t = 0), and the scenario itself, whose law
/// the live lab may change between ticks.
template <class Scenario>
class Loop {
  static_assert(check::scenario<Scenario>());

 public:
  using Sample = typename Scenario::Sample;
  using Observer = typename Scenario::Observer;

  /// Loads the robot, builds the simulation and starts `s` on it.
  explicit Loop(Scenario s)
      : scenario(std::move(s)), model_(load_urdf(robot_path(Scenario::kRobotFile))), observer_(model_),
        sim_(model_, Scenario::settings()) {
    scenario.start(sim_);
  }
  Loop(const Loop&) = delete;  // the Observer refers to model_
  Loop& operator=(const Loop&) = delete;

  /// The instant t = simulation().time(): its Sample, with the torques to apply for the next step.
  Sample tick() { return scenario.tick(observer_, sim_, gains); }
  Simulation& simulation() { return sim_; }              ///< the simulated robot and scene
  const Simulation& simulation() const { return sim_; }  ///< the same, to read
  const Model& model() const { return model_; }          ///< the controller's model of the robot
  const auto& state() const { return observer_.state(); }  ///< the last tick's State
  const Observer& observer() const { return observer_; }   ///< what computed it

  Scenario scenario;    ///< the problem's run: its law, its target
  GainOverrides gains;  ///< live changes to the goal's gains

 private:
  Model model_;
  Observer observer_;
  Simulation sim_;
};

/// What a run of Scenario records.
template <class Scenario>
using ResultOf = RunResult<typename Scenario::Sample, typename Scenario::Summary>;

/// Runs `scenario` on its simulation every 1 ms step for options.duration seconds
/// (run_closed_loop), then summarises it.
template <class Scenario>
ResultOf<Scenario> run(Scenario scenario, const RunOptions& options) {
  Loop<Scenario> loop(std::move(scenario));
  const Scenario& s = loop.scenario;
  ResultOf<Scenario> result = run_closed_loop<ResultOf<Scenario>>(
      loop.simulation(), s.what(), s.csv_columns(), options, [&](double) { return loop.tick(); },
      [&](const typename Scenario::Sample& sample) { return s.csv_row(sample); });
  s.summarise(result, loop.model(), loop.simulation());
  return result;
}

}  // namespace opspace::scenarios
