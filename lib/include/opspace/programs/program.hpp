// One main for the programs that make one run of one problem's scenario: a program describes
// itself once (its name, usage, scenario, summary table, final values and pictures, its live
// lab) and run_program() is its main (hw2-p2, hw2-p3), or run_parsed() once the program has
// read its own command line (hw2-p1). It knows no problem: what it prints and runs comes from
// the description. (hw2-p4 makes two runs per target and answers questions i-iv: its own main.)
#pragma once

#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "opspace/scenarios/loop.hpp"
#include "opspace/visuals/plot.hpp"
#include "opspace/visuals/replay.hpp"
#include "opspace/visuals/visuals.hpp"

#include "opspace/programs/cli.hpp"

#ifdef OPSPACE_LIVE
#include "opspace/live/loop_lab.hpp"

#include "opspace/programs/live.hpp"
#endif

namespace opspace::programs {

/// A program of one scenario, described once.
template <class Scenario>
struct ScenarioProgram {
  using Result = opspace::scenarios::ResultOf<Scenario>;

  std::string name;     ///< e.g. "hw2-p2": the progress lines' and the live page's name
  std::string problem;  ///< the problem's key ("2"): the graded run a --test replays
  std::string heading;  ///< the first line printed, e.g. "problem 2, iiwa ... (solutions/)"
  std::string live_heading;  ///< the same with --live (empty: heading)
  double duration = 0.0;  ///< simulated seconds of the default run
  /// Prints the usage of `program` to stdout (code 0) or stderr and returns `code`.
  int (*usage)(const char* program, int code) = nullptr;
  std::function<Scenario()> scenario;  ///< the scenario, with the student's functions linked
  /// The run's table beside the grader's bounds and the reference (duration, log's path).
  std::function<void(const Result&, double duration, const std::string& csv)> summary;
  /// With --test: the final values of the graded test's series (print_final), of a run with samples.
  std::function<void(const Options&, const Result&)> finals;
  /// The plots of a run of the scenario (live: with the law in force at its end); none if empty.
  std::function<std::vector<opspace::plot::Figure>(const Result&, const Scenario&)> figures;
  /// Its 3D replay; none if empty (a problem without PICTURES).
  std::function<opspace::replay::Scene(const Result&, const Scenario&)> replay_scene;
#ifdef OPSPACE_LIVE
  /// The live lab of the scenario, named after the program.
  std::function<std::unique_ptr<opspace::live::LoopLab<Scenario>>(const std::string& name)> lab;
#endif
};

/// The rest of `program`'s main once `options` are parsed: the watchdog from the environment,
/// --test's duration, then serve it live with --live, or run it once, print its summary (and
/// --test's final values), draw its pictures. Returns the exit code: 0 after a whole run, 1 if
/// it stopped early or threw, 2 after a bad OPSPACE_WATCHDOG.
template <class Scenario>
int run_parsed(const char* argv0, Options& options, const ScenarioProgram<Scenario>& program) {
  if (!watchdog_from_environment(argv0, options)) return 2;
  start_replay(options, program.problem, Scenario::kGradedDuration);
  options.run.progress = &std::cerr;
  options.run.label = program.name;
  const std::string prefix = opspace::visuals::prefix_of(options.run.csv_path);
  std::cout << (options.live && !program.live_heading.empty() ? program.live_heading : program.heading) << "\n";
  if (options.live) {
#ifdef OPSPACE_LIVE
    if (!program.lab) return no_lab(argv0, program.problem);  // its folder declares no LAB
    return guarded(argv0, [&] {
      const auto lab = program.lab(program.name);
      return serve_live(
          *lab, options, prefix, [&] { return program.figures(lab->result(), lab->scenario()); },
          [&] { return program.replay_scene(lab->result(), lab->scenario()); });
    });
#else
    return no_live(argv0);
#endif
  }
  return guarded(argv0, [&] {
    const Scenario scenario = program.scenario();
    const typename ScenarioProgram<Scenario>::Result result = opspace::scenarios::run(scenario, options.run);
    program.summary(result, options.run.duration, options.run.csv_path);
    if (!result.samples.empty()) program.finals(options, result);
    // A problem without PICTURES: no plots and no replay, the exit code finish()'s.
    if (!program.figures || !program.replay_scene) return result.samples.empty() || !result.failure.empty() ? 1 : 0;
    return finish(
        options, prefix, result, [&] { return program.figures(result, scenario); },
        [&] { return program.replay_scene(result, scenario); });
  });
}

/// The main of `program`: parse() the options (the log out/<argv[0]'s name>.csv by default),
/// then run_parsed(). Returns its exit code, or parse()'s (0 after --help, 2 after a bad argument).
template <class Scenario>
int run_program(int argc, char** argv, const ScenarioProgram<Scenario>& program) {
  Options options;
  options.run.duration = program.duration;
  options.run.csv_path = output_path(program_name(argv[0]) + ".csv");
  Program parsing;
  parsing.usage = program.usage;
  const int code = parse(argc, argv, 1, parsing, options);
  if (code >= 0) return code;
  return run_parsed(argv[0], options, program);
}

}  // namespace opspace::programs
