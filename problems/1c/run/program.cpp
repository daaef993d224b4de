// hw2-p1c [options]: problem 1c on the simulated PUMA 560 with the law of exercises/p1c.cpp
// (hw2-p1c) or solutions/p1c.cpp (hw2-p1c-sol).
#include <iostream>
#include <memory>
#include <string>

#include <opspace/hw2/p1c.hpp>
#include <opspace/programs/cli.hpp>
#include <opspace/programs/program.hpp>
#include <problems/1c/run/pictures.hpp>
#include <problems/1c/run/scenario.hpp>

#include "reference_runs.hpp"

#ifdef OPSPACE_LIVE
#include <problems/1c/run/lab.hpp>
#endif

namespace {

namespace p1b = opspace::scenarios::p1b;
namespace p1c = opspace::scenarios::p1c;

int usage(const char* program, int code) {
  (code ? std::cerr : std::cout)
      << "usage: " << program << " [--duration SECONDS] [--csv PATH] [--no-plots] [--no-replay] [--live [--port N]]\n"
      << "       [--test NAME [--seed N]]   replay a graded test's run, as the grader's report prints it\n"
      << "  the PUMA 560 holds its tip at x_d with the tip PD and no joint damping (problem 1c)\n"
      << "  --duration  simulated seconds (default " << p1b::kDefaultDuration << ", at most " << cli::kMaxDuration << ")\n"
      << "  --csv       log file (default out/" << cli::program_name(program) << ".csv in the repository); plots and the 3D replay page are\n"
      << "              written next to it, named after it (docs/visuals.md)\n"
      << "  --no-plots, --no-replay  skip those pictures\n"
      << "  --live      run in real time in the browser, push the arm with the mouse (docs/live.md); until\n"
      << "              Ctrl-C, or --duration simulated seconds. --port N: its port (default: a free one)\n";
  return code;
}

/// The run's results beside the grader's bound and the reference run.
void print_summary(const p1c::Result& r, double duration, const std::string& csv) {
  const p1b::Summary& s = r.summary;
  const p1b::Summary ref = reference::p1c();
  cli::print_summary_start(s.time_reached, duration, reference::kP1cDuration);
  cli::Verdict table(cli::reference_heading(reference::kP1cDuration));
  table.section("after " + cli::show(p1b::kSettleTime, cli::kSeconds));
  table.at_most("tip error, max", s.tip_error_max, p1c::kTipErrorMax, ref.tip_error_max, cli::kMm);
  table.shown("tip error, RMS", s.tip_error_rms, ref.tip_error_rms, cli::kMm);
  table.note("without joint damping the null space swings, and its Coriolis forces move the tip by");
  table.note("centimetres: problem 1b's PART1 (hw2-p1 1) holds it to a millimetre.");
  table.section("over the whole run");
  cli::add_torque_rows(table, s, ref);
  table.print(std::cout, "bash scripts/grade --problem 1c says which test and why");
  cli::print_summary_end(r, csv);
}

/// With --test: the final value of the series the graded test reads (problems/1c/grade/graded.cpp).
void print_finals(const cli::Options& options, const p1c::Result& r) {
  cli::print_final(options, "tip error |x - x_d|", p1b::tip_error(r.samples.back()), "m");
}

/// hw2-p1c, described once: cli::run_program() is its main.
cli::ScenarioProgram<p1c::Scenario> program() {
  cli::ScenarioProgram<p1c::Scenario> program;
  program.name = "hw2-p1c";
  program.problem = "1c";
  program.heading = std::string("problem 1c, tip PD without joint damping (") + OPSPACE_GRADED_LIBRARY + ")";
  program.duration = p1b::kDefaultDuration;
  program.usage = &usage;
  program.scenario = [] { return p1c::scenario(&opspace::hw2::p1c::control); };
  program.summary = &print_summary;
  program.finals = &print_finals;
  program.figures = [](const p1c::Result& r, const p1c::Scenario&) { return p1c::figures(r); };
  program.replay_scene = [](const p1c::Result& r, const p1c::Scenario&) { return p1c::replay_scene(r); };
#ifdef OPSPACE_LIVE
  program.lab = [](const std::string& name) {
    return std::make_unique<opspace::live::P1cLab>(name, &opspace::hw2::p1c::control);
  };
#endif
  return program;
}

}  // namespace

int main(int argc, char** argv) { return cli::run_program(argc, argv, program()); }
