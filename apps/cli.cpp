#include "cli.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>

#include <opspace/scenarios/watchdog.hpp>
#include <opspace/visuals.hpp>

namespace cli {

int parse(int argc, char** argv, int first, const Program& program, Options& options) {
  for (int i = first; i < argc; ++i) {
    const std::string arg = argv[i];
    if (program.help && (arg == "--help" || arg == "-h")) {
      return program.usage(argv[0], 0);
    } else if (arg == "--no-plots") {
      options.plots = false;
    } else if (arg == "--no-replay") {
      options.replay = false;
    } else if (arg == "--duration" && i + 1 < argc) {
      char* end = nullptr;
      options.run.duration = std::strtod(argv[++i], &end);
      if (*end != '\0' || !(options.run.duration > 0.0)) {
        std::cerr << argv[0] << ": --duration needs a positive number of seconds\n";
        return 2;
      }
    } else if (program.csv && arg == "--csv" && i + 1 < argc) {
      options.run.csv_path = argv[++i];
    } else if (!program.extra || !program.extra(arg)) {
      std::cerr << argv[0] << ": unknown argument '" << arg << "'\n";
      return program.usage(argv[0], 2);
    }
  }
  return -1;
}

void publish(const Options& options, const std::string& prefix,
             const std::function<std::vector<opspace::plot::Figure>()>& figures,
             const std::function<opspace::replay::Scene()>& scene) {
  const std::vector<opspace::plot::Figure> drawn =
      options.plots ? figures() : std::vector<opspace::plot::Figure>{};
  if (options.replay) {
    const opspace::replay::Scene replay = scene();
    opspace::visuals::publish(drawn, &replay, prefix, std::cout);
  } else {
    opspace::visuals::publish(drawn, nullptr, prefix, std::cout);
  }
}

std::string reference_heading(double duration) { return "reference (" + show(duration, kSeconds) + ")"; }

void print_summary_start(double time_reached, double duration, double reference_duration) {
  std::cout << std::fixed << std::setprecision(2) << "\nsimulated " << time_reached << " s of "
            << show(duration, kSeconds) << "\n";
  if (std::abs(duration - reference_duration) > 1e-9) {
    std::cout << "note: the grader and the reference run " << show(reference_duration, kSeconds)
              << "; over " << show(duration, kSeconds) << " the comparison below is only indicative\n";
  }
}

std::string output_path(const std::string& name) {
  namespace fs = std::filesystem;
  const char* override_dir = std::getenv("OPSPACE_OUT");
  const fs::path dir = override_dir && *override_dir ? fs::path(override_dir) : fs::path(OPSPACE_OUT_DIR);
  std::error_code ec;
  const fs::path out = fs::weakly_canonical(fs::absolute(dir, ec), ec);
  const fs::path here = fs::weakly_canonical(fs::current_path(ec), ec);
  if (ec) return (dir / name).string();
  // Below the current directory (run from the repository's root): the short relative path.
  const auto [o, h] = std::mismatch(out.begin(), out.end(), here.begin(), here.end());
  if (h == here.end()) return (out.lexically_relative(here) / name).string();
  return (out / name).string();
}

bool watchdog_from_environment(const char* program, Options& options) {
  try {
    options.run.watchdog = opspace::scenarios::watchdog_seconds_from_environment();
    return true;
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return false;
  }
}

int guarded(const char* program, const std::function<int()>& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace cli
