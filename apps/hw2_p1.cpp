// hw2-p1 PART [options]: problem 1b on the simulated PUMA 560 with the control law of
// exercises/p1b.cpp (hw2-p1) or solutions/p1b.cpp (hw2-p1-sol).
#include <iomanip>
#include <iostream>
#include <string>

#include <opspace/hw2/p1b.hpp>
#include <opspace/scenarios.hpp>
#include <opspace/scenarios/p1b_visuals.hpp>
#include <opspace/visuals.hpp>

#include "cli.hpp"

namespace {

namespace p1b = opspace::scenarios::p1b;
using opspace::hw2::p1b::Part;

int usage(const char* program, int code) {
  (code ? std::cerr : std::cout)
      << "usage: " << program << " 1|2|3|compare [--no-joint-damping] [--duration SECONDS] [--csv PATH]\n"
      << "       [--no-plots] [--no-replay]\n"
      << "  1  PART1: hold the tip with PD control and joint damping\n"
      << "     (--no-joint-damping: question ii's variant without it)\n"
      << "  2  PART2: move joint 2 in the null space, pseudo-inverse projector\n"
      << "  3  PART3: move joint 2 in the null space, dynamically consistent projector\n"
      << "  compare  run PART2 and PART3 and overlay their tip drift (out/hw2-p1-compare-drift.png)\n"
      << "  --duration  simulated seconds (default 20, at most " << cli::kMaxDuration << ")\n"
      << "  --csv       log file (default out/hw2-p1-part<PART>.csv); the plots and the replay page\n"
      << "              are written next to it, named after it (docs/visuals.md)\n"
      << "  --no-plots, --no-replay   skip the PNG/SVG plots, the 3D replay page\n";
  return code;
}

void print_summary(const p1b::Result& r, const std::string& csv) {
  const p1b::Summary& s = r.summary;
  std::cout << std::fixed << std::setprecision(2) << "\nsimulated " << s.time_reached << " s\n";
  std::cout << std::setprecision(3) << "tip error after " << p1b::kSettleTime
            << " s:   max " << 1e3 * s.tip_error_max << " mm, RMS " << 1e3 * s.tip_error_rms << " mm\n"
            << "q2 tracking error after " << p1b::kSettleTime << " s: max " << s.q2_error_max
            << " rad, RMS " << s.q2_error_rms << " rad\n";
  cli::print_summary_end(r, csv);
}

/// Runs PART2 and PART3 and draws their tip drift in one figure: the lesson of problem 1b.
int compare(const cli::Options& cli_options, const std::string& prefix) {
  std::cout << "problem 1b, PART2 against PART3 (" << OPSPACE_GRADED_LIBRARY << ")\n";
  opspace::scenarios::RunOptions options = cli_options.run;
  options.csv_path = prefix + "-part2.csv";
  const p1b::Result part2 = p1b::run(Part::kPseudoInverseNullspace, &opspace::hw2::p1b::control, options);
  options.csv_path = prefix + "-part3.csv";
  const p1b::Result part3 = p1b::run(Part::kDynamicallyConsistentNullspace, &opspace::hw2::p1b::control, options);
  std::cout << std::setprecision(3) << "\ntip error after " << p1b::kSettleTime << " s (max, RMS):\n"
            << "  PART2 pseudo-inverse projector:         " << 1e3 * part2.summary.tip_error_max << " mm, "
            << 1e3 * part2.summary.tip_error_rms << " mm\n"
            << "  PART3 dynamically consistent projector: " << 1e3 * part3.summary.tip_error_max << " mm, "
            << 1e3 * part3.summary.tip_error_rms << " mm\n"
            << "logs: " << prefix << "-part2.csv " << prefix << "-part3.csv\n";
  if (cli_options.plots) opspace::visuals::publish({p1b::compare_figure(part2, part3)}, nullptr, prefix, std::cout);
  if (!part2.failure.empty()) std::cout << "PART2 stopped early: " << part2.failure << "\n";
  if (!part3.failure.empty()) std::cout << "PART3 stopped early: " << part3.failure << "\n";
  return part2.failure.empty() && part3.failure.empty() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  cli::P1Command command;
  const int code = cli::parse_p1(argc, argv, &usage, command);
  if (code >= 0) return code;
  const Part part = command.part;
  cli::Options& options = command.options;
  options.run.progress = &std::cerr;
  const std::string prefix = opspace::visuals::prefix_of(options.run.csv_path);
  if (command.comparing) return cli::guarded(argv[0], [&] { return compare(options, prefix); });
  std::cout << "problem 1b, " << p1b::describe(part) << " (" << OPSPACE_GRADED_LIBRARY << ")\n";
  return cli::guarded(argv[0], [&] {
    const p1b::Result result = p1b::run(part, &opspace::hw2::p1b::control, options.run);
    print_summary(result, options.run.csv_path);
    return cli::finish(
        options, prefix, result, [&] { return p1b::figures(result, part); },
        [&] { return p1b::replay_scene(result, part); });
  });
}
