// hw2-p2 [options]: problem 2 on the simulated KUKA iiwa with the functions of exercises/p2.cpp
// (hw2-p2) or solutions/p2.cpp (hw2-p2-sol).
#include <iomanip>
#include <iostream>
#include <string>

#include <opspace/hw2/p2.hpp>
#include <opspace/scenarios.hpp>
#include <opspace/scenarios/p2_visuals.hpp>
#include <opspace/visuals.hpp>

#include "cli.hpp"

namespace {

namespace p2 = opspace::scenarios::p2;

int usage(const char* program, int code) {
  (code ? std::cerr : std::cout)
      << "usage: " << program << " [--duration SECONDS] [--csv PATH] [--no-plots] [--no-replay]\n"
      << "  link7 of the iiwa tracks x_d(t) and lambda_d(t) of problem 2\n"
      << "  --duration  simulated seconds (default " << p2::kDefaultDuration << ", at most " << cli::kMaxDuration << ")\n"
      << "  --csv       log file (default out/hw2-p2.csv); plots and the 3D replay page are\n"
      << "              written next to it, named after it (docs/visuals.md)\n"
      << "  --no-plots, --no-replay  skip those pictures\n";
  return code;
}

void print_summary(const p2::Result& r, const std::string& csv) {
  const p2::Summary& s = r.summary;
  constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;
  std::cout << std::fixed << std::setprecision(2) << "\nsimulated " << s.time_reached << " s\n";
  std::cout << std::setprecision(3) << "position error after " << p2::kSettleTime << " s:    max "
            << 1e3 * s.position_error_max << " mm, RMS " << 1e3 * s.position_error_rms << " mm\n"
            << "orientation error after " << p2::kSettleTime << " s: max " << kDegPerRad * s.orientation_error_max
            << " deg, RMS " << kDegPerRad * s.orientation_error_rms << " deg\n"
            << "smallest joint-limit margin (negative: past the limit): " << kDegPerRad * s.joint_limit_margin << " deg (joint "
            << s.joint_limit_joint + 1 << ")\n"
            << "joint drift over the last period: " << kDegPerRad * s.joint_drift_per_period << " deg (joint "
            << s.joint_drift_joint + 1 << ")\n";
  cli::print_summary_end(r, csv);
}

}  // namespace

int main(int argc, char** argv) {
  cli::Options options;
  options.run.duration = p2::kDefaultDuration;
  options.run.csv_path = "out/hw2-p2.csv";
  cli::Program program;
  program.usage = &usage;
  const int code = cli::parse(argc, argv, 1, program, options);
  if (code >= 0) return code;
  options.run.progress = &std::cerr;
  std::cout << "problem 2, iiwa position + Euler-parameter tracking (" << OPSPACE_GRADED_LIBRARY << ")\n";
  return cli::guarded(argv[0], [&] {
    const p2::Result result =
        p2::run(&opspace::hw2::p2::control, &opspace::hw2::p2::desired_acceleration, options.run);
    print_summary(result, options.run.csv_path);
    return cli::finish(
        options, opspace::visuals::prefix_of(options.run.csv_path), result, [&] { return p2::figures(result); },
        [&] { return p2::replay_scene(result); });
  });
}
