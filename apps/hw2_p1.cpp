// hw2-p1 PART [options]: problem 1b on the simulated PUMA 560 with the control law of
// exercises/p1b.cpp (hw2-p1) or solutions/p1b.cpp (hw2-p1-sol).
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <string>

#include <opspace/hw2/p1b.hpp>
#include <opspace/scenarios.hpp>

namespace {

namespace p1b = opspace::scenarios::p1b;
using opspace::hw2::p1b::Part;

int usage(const char* program, int code) {
  (code ? std::cerr : std::cout)
      << "usage: " << program << " 1|2|3 [--no-joint-damping] [--duration SECONDS] [--csv PATH]\n"
      << "  1  PART1: hold the tip with PD control and joint damping\n"
      << "     (--no-joint-damping: question ii's variant without it)\n"
      << "  2  PART2: move joint 2 in the null space, pseudo-inverse projector\n"
      << "  3  PART3: move joint 2 in the null space, dynamically consistent projector\n"
      << "  --duration  simulated seconds (default 20)\n"
      << "  --csv       log file (default out/hw2-p1-part<PART>.csv)\n";
  return code;
}

void print_summary(const p1b::Result& r, const std::string& csv) {
  const p1b::Summary& s = r.summary;
  std::cout << std::fixed << std::setprecision(2) << "\nsimulated " << s.time_reached << " s\n";
  std::cout << std::setprecision(3) << "tip error after " << p1b::kSettleTime
            << " s:   max " << 1e3 * s.tip_error_max << " mm, RMS " << 1e3 * s.tip_error_rms << " mm\n"
            << "q2 tracking error after " << p1b::kSettleTime << " s: max " << s.q2_error_max
            << " rad, RMS " << s.q2_error_rms << " rad\n"
            << std::setprecision(1) << "peak joint torque:        " << s.peak_torque << " N m (joint "
            << s.peak_torque_joint + 1 << ")\n"
            << "torques clamped to limits: " << s.clamped_steps << " joint-steps\n";
  if (!csv.empty()) std::cout << "log: " << csv << "\n";
  if (!r.failure.empty()) std::cout << "the run stopped early: " << r.failure << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage(argv[0], 2);
  if (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) return usage(argv[0], 0);
  const std::string part_arg = argv[1];
  if (part_arg != "1" && part_arg != "2" && part_arg != "3") {
    std::cerr << argv[0] << ": unknown part '" << part_arg << "'\n";
    return usage(argv[0], 2);
  }
  Part part = static_cast<Part>(std::stoi(part_arg));
  opspace::scenarios::RunOptions options;
  options.csv_path = "out/hw2-p1-part" + part_arg + ".csv";
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--no-joint-damping" && part == Part::kTipPd) {
      part = Part::kTipPdWithoutJointDamping;
      options.csv_path = "out/hw2-p1-part1-no-damping.csv";
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
  std::cout << "problem 1b, " << p1b::describe(part) << " (" << OPSPACE_GRADED_LIBRARY << ")\n";
  try {
    const p1b::Result result = p1b::run(part, &opspace::hw2::p1b::control, options);
    print_summary(result, options.csv_path);
    return result.failure.empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << argv[0] << ": " << e.what() << "\n";
    return 1;
  }
}
