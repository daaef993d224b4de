// hw2-p3 [options]: problem 3 on the simulated KUKA iiwa pushing on the plane x = 0.05, with the
// functions of exercises/p3.cpp (hw2-p3) or solutions/p3.cpp (hw2-p3-sol).
#include <iomanip>
#include <iostream>
#include <string>

#include <opspace/hw2/p3.hpp>
#include <opspace/scenarios.hpp>
#include <opspace/scenarios/p3_visuals.hpp>
#include <opspace/visuals.hpp>

#include "cli.hpp"

namespace {

namespace p3 = opspace::scenarios::p3;

int usage(const char* program, int code) {
  (code ? std::cerr : std::cout)
      << "usage: " << program << " [--duration SECONDS] [--csv PATH] [--no-plots] [--no-replay]\n"
      << "  link7's tool pushes 10 N on the plane x = 0.05 and tracks y_d, z_d and the rotation about x\n"
      << "  --duration  simulated seconds (default " << p3::kDefaultDuration << ", at most " << cli::kMaxDuration << ")\n"
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
            << "  link7's origin along x:      " << 1e3 * s.x_min << " to " << 1e3 * s.x_max << " mm\n";
  cli::print_summary_end(r, csv);
}

}  // namespace

int main(int argc, char** argv) {
  cli::Options options;
  options.run.duration = p3::kDefaultDuration;
  options.run.csv_path = "out/hw2-p3.csv";
  cli::Program program;
  program.usage = &usage;
  const int code = cli::parse(argc, argv, 1, program, options);
  if (code >= 0) return code;
  options.run.progress = &std::cerr;
  std::cout << "problem 3, iiwa unified motion and force control against a plane (" << OPSPACE_GRADED_LIBRARY
            << ")\n";
  return cli::guarded(argv[0], [&] {
    const p3::Result result = p3::run(&opspace::hw2::p3::control, options.run);
    print_summary(result, options.run.csv_path);
    return cli::finish(
        options, opspace::visuals::prefix_of(options.run.csv_path), result, [&] { return p3::figures(result); },
        [&] { return p3::replay_scene(result); });
  });
}
