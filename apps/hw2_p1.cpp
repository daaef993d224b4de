// hw2-p1 PART [options]: problem 1b on the simulated PUMA 560 with the control law of
// exercises/p1b.cpp (hw2-p1) or solutions/p1b.cpp (hw2-p1-sol).
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <string>

#include <opspace/hw2/p1b.hpp>
#include <opspace/scenarios.hpp>
#include <opspace/scenarios/p1b_visuals.hpp>
#include <opspace/visuals.hpp>

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
      << "  --duration  simulated seconds (default 20)\n"
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
            << " rad, RMS " << s.q2_error_rms << " rad\n"
            << std::setprecision(1) << "peak joint torque:        " << s.peak_torque << " N m (joint "
            << s.peak_torque_joint + 1 << ")\n"
            << "torques clamped to limits: " << s.clamped_steps << " joint-steps\n";
  if (!csv.empty()) std::cout << "log: " << csv << "\n";
  if (!r.failure.empty()) std::cout << "the run stopped early: " << r.failure << "\n";
}

/// What to write after a run.
struct Pictures {
  bool plots = true;
  bool replay = true;
};

/// Runs PART2 and PART3 and draws their tip drift in one figure: the lesson of problem 1b.
int compare(const opspace::scenarios::RunOptions& base, const std::string& prefix, const Pictures& pictures) {
  std::cout << "problem 1b, PART2 against PART3 (" << OPSPACE_GRADED_LIBRARY << ")\n";
  opspace::scenarios::RunOptions options = base;
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
  if (pictures.plots) opspace::visuals::publish({p1b::compare_figure(part2, part3)}, nullptr, prefix, std::cout);
  if (!part2.failure.empty()) std::cout << "PART2 stopped early: " << part2.failure << "\n";
  if (!part3.failure.empty()) std::cout << "PART3 stopped early: " << part3.failure << "\n";
  return part2.failure.empty() && part3.failure.empty() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage(argv[0], 2);
  if (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) return usage(argv[0], 0);
  const std::string part_arg = argv[1];
  const bool comparing = part_arg == "compare";
  if (part_arg != "1" && part_arg != "2" && part_arg != "3" && !comparing) {
    std::cerr << argv[0] << ": unknown part '" << part_arg << "'\n";
    return usage(argv[0], 2);
  }
  Part part = comparing ? Part::kPseudoInverseNullspace : static_cast<Part>(std::stoi(part_arg));
  opspace::scenarios::RunOptions options;
  options.csv_path = comparing ? "out/hw2-p1-compare.csv" : "out/hw2-p1-part" + part_arg + ".csv";
  Pictures pictures;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--no-plots") {
      pictures.plots = false;
    } else if (arg == "--no-replay") {
      pictures.replay = false;
    } else if (arg == "--no-joint-damping" && part == Part::kTipPd && !comparing) {
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
  const std::string prefix = opspace::visuals::prefix_of(options.csv_path);
  if (comparing) {
    try {
      return compare(options, prefix, pictures);
    } catch (const std::exception& e) {
      std::cerr << argv[0] << ": " << e.what() << "\n";
      return 1;
    }
  }
  std::cout << "problem 1b, " << p1b::describe(part) << " (" << OPSPACE_GRADED_LIBRARY << ")\n";
  try {
    const p1b::Result result = p1b::run(part, &opspace::hw2::p1b::control, options);
    print_summary(result, options.csv_path);
    // After the run: drawing never slows the control loop.
    if (result.samples.empty()) {
      std::cout << "note:   no plots or replay: the run logged no sample\n";
      return 1;
    }
    const std::vector<opspace::plot::Figure> figures =
        pictures.plots ? p1b::figures(result, part) : std::vector<opspace::plot::Figure>{};
    if (pictures.replay) {
      const opspace::replay::Scene scene = p1b::replay_scene(result, part);
      opspace::visuals::publish(figures, &scene, prefix, std::cout);
    } else {
      opspace::visuals::publish(figures, nullptr, prefix, std::cout);
    }
    return result.failure.empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << argv[0] << ": " << e.what() << "\n";
    return 1;
  }
}
