// hw2-p3 [options]: problem 3 on the simulated KUKA iiwa pushing on the plane x = 0.05, with the
// functions of exercises/p3.cpp (hw2-p3) or solutions/p3.cpp (hw2-p3-sol).
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <string>

#include <opspace/hw2/p3.hpp>
#include <opspace/scenarios.hpp>
#include <opspace/scenarios/p3_visuals.hpp>
#include <opspace/visuals.hpp>

namespace {

namespace p3 = opspace::scenarios::p3;

int usage(const char* program, int code) {
  (code ? std::cerr : std::cout)
      << "usage: " << program << " [--duration SECONDS] [--csv PATH] [--no-plots] [--no-replay]\n"
      << "  link7's tool pushes 10 N on the plane x = 0.05 and tracks y_d, z_d and the rotation about x\n"
      << "  --duration  simulated seconds (default " << p3::kDefaultDuration << ")\n"
      << "  --csv       log file (default out/hw2-p3.csv); the plots (PNG, SVG) and the replay page\n"
      << "              (HTML) are written next to it, named after it (docs/visuals.md)\n"
      << "  --no-plots, --no-replay   skip the PNG/SVG plots, the 3D replay page\n";
  return code;
}

void print_summary(const p3::Result& r, const std::string& csv) {
  const p3::Summary& s = r.summary;
  constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;
  std::cout << std::fixed << std::setprecision(2) << "\nsimulated " << s.time_reached << " s\n";
  if (s.first_contact_time < 0) {
    std::cout << "the tool never touched the plane\n";
  } else {
    std::cout << std::setprecision(3) << "first contact at t = " << s.first_contact_time << " s\n";
  }
  std::cout << std::setprecision(3) << "after " << p3::kSettleTime << " s:\n"
            << "  contact force F_x:           mean " << s.force_mean << " N (desired " << p3::kPushForce << " N)\n"
            << "  force error |F_x - 10|:      mean " << s.force_error_mean << " N, peak " << s.force_error_max
            << " N (peak of the 10 ms average " << s.force_error_max_10ms << " N)\n"
            << "  steps without contact:       " << s.contact_lost_samples << "\n"
            << "  contact moment |(M_y, M_z)| about link7's origin: max " << s.moment_yz_max << " N m\n"
            << "  y, z tracking error:         max " << 1e3 * s.yz_error_max << " mm, RMS " << 1e3 * s.yz_error_rms
            << " mm\n"
            << "  rotation-about-x error:      max " << kDegPerRad * s.rotation_x_error_max << " deg, RMS "
            << kDegPerRad * s.rotation_x_error_rms << " deg\n"
            << "  tool tilt against the plane: max " << kDegPerRad * s.tilt_max << " deg, RMS "
            << kDegPerRad * s.tilt_rms << " deg\n"
            << "  link7's origin along x:      " << 1e3 * s.x_min << " to " << 1e3 * s.x_max << " mm\n"
            << std::setprecision(1) << "peak joint torque:        " << s.peak_torque << " N m (joint "
            << s.peak_torque_joint + 1 << ")\n"
            << "torques clamped to limits: " << s.clamped_steps << " joint-steps\n";
  if (!csv.empty()) std::cout << "log: " << csv << "\n";
  if (!r.failure.empty()) std::cout << "the run stopped early: " << r.failure << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  opspace::scenarios::RunOptions options;
  options.duration = p3::kDefaultDuration;
  options.csv_path = "out/hw2-p3.csv";
  bool plots = true, replay = true;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      return usage(argv[0], 0);
    } else if (arg == "--no-plots") {
      plots = false;
    } else if (arg == "--no-replay") {
      replay = false;
    } else if (arg == "--duration" && i + 1 < argc) {
      char* end = nullptr;
      options.duration = std::strtod(argv[++i], &end);
      if (*end != '\0' || !(options.duration > 0.0)) {
        std::cerr << argv[0] << ": --duration needs a positive number of seconds\n";
        return 2;
      }
    } else if (arg == "--csv" && i + 1 < argc) {
      options.csv_path = argv[++i];
    } else {
      std::cerr << argv[0] << ": unknown argument '" << arg << "'\n";
      return usage(argv[0], 2);
    }
  }
  options.progress = &std::cerr;
  std::cout << "problem 3, iiwa unified motion and force control against a plane (" << OPSPACE_GRADED_LIBRARY
            << ")\n";
  try {
    const p3::Result result = p3::run(&opspace::hw2::p3::control, options);
    print_summary(result, options.csv_path);
    // After the run: drawing never slows the control loop.
    if (!result.samples.empty()) {
      const std::vector<opspace::plot::Figure> figures =
          plots ? p3::figures(result) : std::vector<opspace::plot::Figure>{};
      const std::string prefix = opspace::visuals::prefix_of(options.csv_path);
      if (replay) {
        const opspace::replay::Scene scene = p3::replay_scene(result);
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
