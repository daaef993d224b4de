// One main for the programs that make one run of one problem's scenario (hw2-p2, hw2-p3): a
// program describes itself once (its name, usage, scenario, summary table, final values and
// pictures, its live lab) and run_program() is its main. It knows no problem: what it prints
// and runs comes from the description.
#pragma once

#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <opspace/scenarios/loop.hpp>
#include <opspace/visuals/plot.hpp>
#include <opspace/visuals/replay.hpp>
#include <opspace/visuals/visuals.hpp>

#include "cli.hpp"

#ifdef OPSPACE_LIVE
#include <opspace/live/loop_lab.hpp>

#include "live.hpp"
#endif

namespace cli {

/// A program of one scenario, described once.
template <class Scenario>
struct ScenarioProgram {
  using Result = opspace::scenarios::ResultOf<Scenario>;

  std::string name;     ///< e.g. "hw2-p2": the progress lines' and the live page's name
  std::string problem;  ///< the problem's key ("2"): the graded run a --test replays
  std::string heading;  ///< the first line printed, e.g. "problem 2, iiwa ... (solutions/)"
  double duration = 0.0;  ///< simulated seconds of the default run
  /// Prints the usage of `program` to stdout (code 0) or stderr and returns `code`.
  int (*usage)(const char* program, int code) = nullptr;
  std::function<Scenario()> scenario;  ///< the scenario, with the student's functions linked
  /// The run's table beside the grader's bounds and the reference (duration, log's path).
  std::function<void(const Result&, double duration, const std::string& csv)> summary;
  /// With --test: the final values of the graded test's series (print_final), of a run with samples.
  std::function<void(const Options&, const Result&)> finals;
  std::function<std::vector<opspace::plot::Figure>(const Result&)> figures;  ///< the plots of a run
  std::function<opspace::replay::Scene(const Result&)> replay_scene;        ///< its 3D replay
#ifdef OPSPACE_LIVE
  /// The live lab of the scenario, named after the program.
  std::function<std::unique_ptr<opspace::live::LoopLab<Scenario>>(const std::string& name)> lab;
#endif
};

/// The main of `program`: parse() the options (the log out/<argv[0]'s name>.csv by default),
/// then serve it live with --live, or run it once, print its summary (and --test's final
/// values), draw its pictures. Returns the exit code: 0 after a whole run, 1 if it stopped
/// early or threw, 2 after a bad argument.
template <class Scenario>
int run_program(int argc, char** argv, const ScenarioProgram<Scenario>& program) {
  Options options;
  options.run.duration = program.duration;
  options.run.csv_path = output_path(program_name(argv[0]) + ".csv");
  Program parsing;
  parsing.usage = program.usage;
  const int code = parse(argc, argv, 1, parsing, options);
  if (code >= 0) return code;
  if (!watchdog_from_environment(argv[0], options)) return 2;
  start_replay(options, program.problem);
  options.run.progress = &std::cerr;
  options.run.label = program.name;
  std::cout << program.heading << "\n";
  const std::string prefix = opspace::visuals::prefix_of(options.run.csv_path);
  if (options.live) {
#ifdef OPSPACE_LIVE
    return guarded(argv[0], [&] {
      const auto lab = program.lab(program.name);
      return serve_live(
          *lab, options, prefix, [&] { return program.figures(lab->result()); },
          [&] { return program.replay_scene(lab->result()); });
    });
#else
    return no_live(argv[0]);
#endif
  }
  return guarded(argv[0], [&] {
    const typename ScenarioProgram<Scenario>::Result result = opspace::scenarios::run(program.scenario(), options.run);
    program.summary(result, options.run.duration, options.run.csv_path);
    if (!result.samples.empty()) program.finals(options, result);
    return finish(
        options, prefix, result, [&] { return program.figures(result); },
        [&] { return program.replay_scene(result); });
  });
}

}  // namespace cli
