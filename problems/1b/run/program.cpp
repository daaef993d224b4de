// hw2-p1 PART [options]: problem 1b on the simulated PUMA 560 with the control law of
// exercises/p1b.cpp (hw2-p1) or solutions/p1b.cpp (hw2-p1-sol).
#include <algorithm>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

#include <problems/1b/contract.hpp>
#include <problems/1b/run/scenario.hpp>
#include "opspace/scenarios/common.hpp"
#include <problems/1b/run/pictures.hpp>
#include "opspace/visuals/visuals.hpp"

#include "opspace/programs/cli.hpp"
#include "command.hpp"
#include "opspace/programs/program.hpp"
#include "reference_runs.hpp"

#ifdef OPSPACE_LIVE
#include <problems/1b/run/lab.hpp>
#endif

namespace programs = opspace::programs;

namespace {

namespace p1b = opspace::scenarios::p1b;
using opspace::hw2::p1b::Part;

int usage(const char* program, int code) {
  (code ? std::cerr : std::cout)
      << "usage: " << program << " 1|2|3|compare [--no-joint-damping] [--duration SECONDS] [--csv PATH]\n"
      << "       [--no-plots] [--no-replay] [--live [--port N]] [--test NAME [--seed N]]\n"
      << "  1  PART1: hold the tip with PD control and joint damping\n"
      << "     (--no-joint-damping: question ii's variant without it)\n"
      << "  2  PART2: move joint 2 in the null space, pseudo-inverse projector\n"
      << "  3  PART3: move joint 2 in the null space, dynamically consistent projector\n"
      << "  compare  run PART2 and PART3 and overlay their tip drift (out/" << programs::program_name(program) << "-compare-drift.png)\n"
      << "  --duration  simulated seconds (default " << p1b::kDefaultDuration << ", as the grader; at most "
      << programs::kMaxDuration << ")\n"
      << "  --csv       log file (default out/" << programs::program_name(program) << "-part<PART>.csv in the repository); the plots and the replay page\n"
      << "              are written next to it, named after it (docs/visuals.md)\n"
      << "  --no-plots, --no-replay   skip the PNG/SVG plots, the 3D replay page\n"
      << "  --live      run in real time in the browser: push the arm, switch PART (docs/live.md); until\n"
      << "              Ctrl-C, or --duration simulated seconds. --port N: its port (default: a free one)\n"
      << "  --test      replay a graded test's run (the grader's report prints the command): its\n"
      << "              duration, and the final values its figure ends with; --seed: the grading's\n";
  return code;
}

/// The run's results beside the grader's bounds for `part` and the reference run. Only what
/// the part controls: PART1 has no joint task, so no q2 error.
void print_summary(Part part, const p1b::Result& r, double duration, const std::string& csv) {
  const p1b::Summary& s = r.summary;
  const p1b::Summary ref = reference::p1b(part);
  programs::print_summary_start(s.time_reached, duration, reference::kP1bDuration);
  programs::Verdict table(programs::reference_heading(reference::kP1bDuration));
  table.section("after " + programs::show(p1b::kSettleTime, programs::kSeconds));
  switch (part) {
    case Part::kTipPd:
      table.at_most("tip error, RMS", s.tip_error_rms, p1b::kPart1TipErrorRmsMax, ref.tip_error_rms, programs::kMm);
      table.shown("tip error, max", s.tip_error_max, ref.tip_error_max, programs::kMm);
      break;
    case Part::kTipPdWithoutJointDamping:
      table.shown("tip error, RMS", s.tip_error_rms, ref.tip_error_rms, programs::kMm);
      table.shown("tip error, max", s.tip_error_max, ref.tip_error_max, programs::kMm);
      table.note("question ii's variant: the grader checks its law only. Without joint damping the arm");
      table.note("swings in the null space, and its Coriolis forces move the tip by centimetres.");
      break;
    case Part::kPseudoInverseNullspace:
      table.row("tip error, RMS", programs::show(s.tip_error_rms, programs::kMm),
                ">= " + programs::show_bound(p1b::kPart2OverPart3TipErrorRmsMin, programs::kNone) + " x PART3's",
                programs::show(ref.tip_error_rms, programs::kMm));
      table.note("the pseudo-inverse projector lets the joint task push the tip: the point of PART2.");
      table.note("`hw2-p1 compare` runs PART2 and PART3 and checks the ratio. PART2 is chaotic: round-off");
      table.note("alone moves its numbers by tens of percent, so a correct law need not match the reference.");
      table.shown("tip error, max", s.tip_error_max, ref.tip_error_max, programs::kMm);
      table.at_most("q2 tracking error, max", s.q2_error_max, p1b::kPart2Q2ErrorMax, ref.q2_error_max, programs::kRad);
      table.shown("q2 tracking error, RMS", s.q2_error_rms, ref.q2_error_rms, programs::kRad);
      break;
    case Part::kDynamicallyConsistentNullspace:
      table.at_most("tip error, max", s.tip_error_max, p1b::kPart3TipErrorMax, ref.tip_error_max, programs::kMm);
      table.shown("tip error, RMS", s.tip_error_rms, ref.tip_error_rms, programs::kMm);
      table.at_most("q2 tracking error, max", s.q2_error_max, p1b::kPart3Q2ErrorMax, ref.q2_error_max, programs::kRad);
      table.shown("q2 tracking error, RMS", s.q2_error_rms, ref.q2_error_rms, programs::kRad);
      break;
  }
  table.section("over the whole run");
  programs::add_torque_rows(table, s, ref);
  table.print(std::cout, "bash scripts/grade --problem 1b says which test and why");
  programs::print_summary_end(r, csv);
}

/// With --test: the final values of the series the graded tests read of `part`'s run, named as
/// the report's figures name them (problems/1b/grade/graded.cpp).
void print_finals(const programs::Options& options, Part part, const p1b::Result& r) {
  if (r.samples.empty()) return;
  const std::string name = part == Part::kTipPd ? "PART1" : part == Part::kPseudoInverseNullspace ? "PART2" : "PART3";
  programs::print_final(options, name + " tip error |x - x_d|", p1b::tip_error(r.samples.back()), "m");
  if (part != Part::kTipPd && part != Part::kTipPdWithoutJointDamping)
    programs::print_final(options, name + " joint 2 tracking error |q2 - q2_d|", p1b::q2_error(r.samples.back()), "rad");
}

/// Runs PART2 and PART3 and draws their tip drift in one figure: the lesson of problem 1b.
int compare(const programs::Options& cli_options, const std::string& prefix) {
  std::cout << "problem 1b, PART2 against PART3 (" << OPSPACE_GRADED_LIBRARY << ")\n";
  opspace::scenarios::RunOptions options = cli_options.run;
  options.csv_path = prefix + "-part2.csv";
  const p1b::Result part2 = p1b::run(Part::kPseudoInverseNullspace, &opspace::hw2::p1b::control, options);
  options.csv_path = prefix + "-part3.csv";
  const p1b::Result part3 = p1b::run(Part::kDynamicallyConsistentNullspace, &opspace::hw2::p1b::control, options);
  const p1b::Summary& s2 = part2.summary;
  const p1b::Summary& s3 = part3.summary;
  const p1b::Summary ref2 = reference::p1b(Part::kPseudoInverseNullspace);
  const p1b::Summary ref3 = reference::p1b(Part::kDynamicallyConsistentNullspace);
  const auto ratio = [](const p1b::Summary& a, const p1b::Summary& b) {
    return a.tip_error_rms / std::max(b.tip_error_rms, 1e-9);  // as the grader divides
  };
  programs::print_summary_start(std::min(s2.time_reached, s3.time_reached), options.duration, reference::kP1bDuration);
  programs::Verdict table(programs::reference_heading(reference::kP1bDuration));
  table.section("tip error after " + programs::show(p1b::kSettleTime, programs::kSeconds));
  table.shown("PART2 pseudo-inverse, RMS", s2.tip_error_rms, ref2.tip_error_rms, programs::kMm);
  table.shown("PART2 pseudo-inverse, max", s2.tip_error_max, ref2.tip_error_max, programs::kMm);
  table.shown("PART3 dyn. consistent, RMS", s3.tip_error_rms, ref3.tip_error_rms, programs::kMm);
  table.at_most("PART3 dyn. consistent, max", s3.tip_error_max, p1b::kPart3TipErrorMax, ref3.tip_error_max, programs::kMm);
  table.at_least("RMS of PART2 over PART3's", ratio(s2, s3), p1b::kPart2OverPart3TipErrorRmsMin, ratio(ref2, ref3),
                 programs::kNone);
  table.note("PART2 is chaotic: round-off alone moves its numbers by tens of percent.");
  table.print(std::cout, "bash scripts/grade --problem 1b says which test and why");
  std::cout << "logs: " << prefix << "-part2.csv " << prefix << "-part3.csv\n";
  print_finals(cli_options, Part::kPseudoInverseNullspace, part2);
  print_finals(cli_options, Part::kDynamicallyConsistentNullspace, part3);
  if (cli_options.plots) opspace::visuals::publish({p1b::compare_figure(part2, part3)}, nullptr, prefix, std::cout);
  if (!part2.failure.empty()) std::cout << "PART2 stopped early: " << part2.failure << "\n";
  if (!part3.failure.empty()) std::cout << "PART3 stopped early: " << part3.failure << "\n";
  return part2.failure.empty() && part3.failure.empty() ? 0 : 1;
}

/// hw2-p1 for `part` (but compare), described once: programs::run_parsed() is the rest of its main.
programs::ScenarioProgram<p1b::Scenario> program(Part part) {
  programs::ScenarioProgram<p1b::Scenario> program;
  program.name = "hw2-p1";
  program.problem = "1b";
  program.heading = "problem 1b, " + p1b::describe(part) + " (" + OPSPACE_GRADED_LIBRARY + ")";
  program.live_heading = "problem 1b live, " + p1b::describe(part) + " (" + OPSPACE_GRADED_LIBRARY + ")";
  program.duration = p1b::kDefaultDuration;
  program.usage = &usage;
  program.scenario = [part] { return p1b::Scenario(part, &opspace::hw2::p1b::control); };
  program.summary = [part](const p1b::Result& r, double duration, const std::string& csv) {
    print_summary(part, r, duration, csv);
  };
  program.finals = [part](const programs::Options& options, const p1b::Result& r) { print_finals(options, part, r); };
  program.figures = [](const p1b::Result& r, const p1b::Scenario& s) { return p1b::figures(r, s.part); };
  program.replay_scene = [](const p1b::Result& r, const p1b::Scenario& s) { return p1b::replay_scene(r, s.part); };
#ifdef OPSPACE_LIVE
  program.lab = [part](const std::string& name) {
    auto lab = std::make_unique<opspace::live::P1bLab>(name, part, &opspace::hw2::p1b::control);
    // The page draws the reference's tip path of the law in force beside the run: its ghost.
    lab->set_reference(reference::kP1bTipPathStep, &reference::p1b_tip_path);
    return lab;
  };
#endif
  return program;
}

}  // namespace

int main(int argc, char** argv) {
  programs::P1Command command;
  command.options.run.duration = p1b::kDefaultDuration;
  const int code = programs::parse_p1(argc, argv, &usage, command);
  if (code >= 0) return code;
  if (!command.comparing) return programs::run_parsed(argv[0], command.options, program(command.part));
  programs::Options& options = command.options;
  if (!programs::watchdog_from_environment(argv[0], options)) return 2;
  programs::start_replay(options, "1b", p1b::Scenario::kGradedDuration);
  options.run.progress = &std::cerr;
  options.run.label = "hw2-p1";
  const std::string prefix = opspace::visuals::prefix_of(options.run.csv_path);
  return programs::guarded(argv[0], [&] { return compare(options, prefix); });
}
