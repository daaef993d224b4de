// hw2-p2 [options]: problem 2 on the simulated KUKA iiwa with the functions of exercises/p2.cpp
// (hw2-p2) or solutions/p2.cpp (hw2-p2-sol).
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <string>

#include <opspace/hw2/p2.hpp>
#include <opspace/scenarios.hpp>
#include <opspace/scenarios/p2_visuals.hpp>
#include <opspace/visuals.hpp>

namespace {

namespace p2 = opspace::scenarios::p2;

int usage(const char* program, int code) {
  (code ? std::cerr : std::cout)
      << "usage: " << program << " [--duration SECONDS] [--csv PATH] [--no-plots] [--no-replay]\n"
      << "  link7 of the iiwa tracks x_d(t) and lambda_d(t) of problem 2\n"
      << "  --duration  simulated seconds (default " << p2::kDefaultDuration << ")\n"
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
            << s.joint_drift_joint + 1 << ")\n"
            << std::setprecision(1) << "peak joint torque:        " << s.peak_torque << " N m (joint "
            << s.peak_torque_joint + 1 << ")\n"
            << "torques clamped to limits: " << s.clamped_steps << " joint-steps\n";
  if (!csv.empty()) std::cout << "log: " << csv << "\n";
  if (!r.failure.empty()) std::cout << "the run stopped early: " << r.failure << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  opspace::scenarios::RunOptions options;
  options.duration = p2::kDefaultDuration;
  options.csv_path = "out/hw2-p2.csv";
  bool plots = true, replay = true;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      return usage(argv[0], 0);
    } else if (arg == "--duration" && i + 1 < argc) {
      char* end = nullptr;
      options.duration = std::strtod(argv[++i], &end);
      if (*end != '\0' || !(options.duration > 0.0)) {
        std::cerr << argv[0] << ": --duration needs a positive number of seconds\n";
        return 2;
      }
    } else if (arg == "--csv" && i + 1 < argc) {
      options.csv_path = argv[++i];
    } else if (arg == "--no-plots") {
      plots = false;
    } else if (arg == "--no-replay") {
      replay = false;
    } else {
      std::cerr << argv[0] << ": unknown argument '" << arg << "'\n";
      return usage(argv[0], 2);
    }
  }
  options.progress = &std::cerr;
  std::cout << "problem 2, iiwa position + Euler-parameter tracking (" << OPSPACE_GRADED_LIBRARY << ")\n";
  try {
    const p2::Result result =
        p2::run(&opspace::hw2::p2::control, &opspace::hw2::p2::desired_acceleration, options);
    print_summary(result, options.csv_path);
    // After the run: drawing never slows the control loop.
    if (!result.samples.empty()) {
      const std::string prefix = opspace::visuals::prefix_of(options.csv_path);
      const std::vector<opspace::plot::Figure> figures = plots ? p2::figures(result) : std::vector<opspace::plot::Figure>{};
      if (replay) {
        const opspace::replay::Scene scene = p2::replay_scene(result);
        opspace::visuals::publish(figures, &scene, prefix, std::cout);
      } else {
        opspace::visuals::publish(figures, nullptr, prefix, std::cout);
      }
    }
    return result.failure.empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << argv[0] << ": " << e.what() << "\n";
    return 1;
  }
}
