#include "opspace/programs/cli.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <filesystem>

#include "opspace/scenarios/watchdog.hpp"
#include "opspace/visuals/visuals.hpp"

namespace opspace::programs {

int refuse(const char* program, const std::string& message) {
  std::cerr << program << ": " << message << "\n";
  return 2;
}


int parse(int argc, char** argv, int first, const Program& program, Options& options) {
  for (int i = first; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (program.help && (arg == "--help" || arg == "-h")) {
      return program.usage(argv[0], 0);
    } else if (arg == "--no-plots") {
      options.plots = false;
    } else if (arg == "--no-replay") {
      options.replay = false;
    } else if (arg == "--duration" && has_value) {
      const std::string value = argv[++i];
      char* end = nullptr;
      const double duration = std::strtod(value.c_str(), &end);
      // strtod also reads "inf", "nan" and "1e999" (as inf): the bounds refuse them.
      if (value.empty() || *end != '\0' || !(duration > 0.0 && duration <= kMaxDuration)) {
        std::ostringstream s;
        s << "--duration needs a number of seconds in (0, " << kMaxDuration << "], not '" << value << "'";
        return refuse(argv[0], s.str());
      }
      options.run.duration = duration;
      options.duration_given = true;
    } else if (arg == "--live") {
      options.live = true;
    } else if (arg == "--test" && has_value) {
      options.test = argv[++i];
      if (options.test.empty()) return refuse(argv[0], "--test needs the name of a graded test, as the report prints it");
    } else if (arg == "--seed" && has_value) {
      const std::string value = argv[++i];
      char* end = nullptr;
      options.seed = std::strtoull(value.c_str(), &end, 10);
      if (value.empty() || *end != '\0' || value[0] == '-' || options.seed == 0)
        return refuse(argv[0], "--seed needs a positive whole number, not '" + value + "'");
    } else if (arg == "--port" && has_value) {
      const std::string value = argv[++i];
      char* end = nullptr;
      const long port = std::strtol(value.c_str(), &end, 10);
      if (value.empty() || *end != '\0' || port < 0 || port > 65535) {
        return refuse(argv[0], "--port needs a port number from 0 (any free port) to 65535, not '" + value + "'");
      }
      options.port = static_cast<int>(port);
    } else if (program.csv && arg == "--csv" && has_value) {
      options.run.csv_path = argv[++i];
      if (options.run.csv_path.empty()) return refuse(argv[0], "--csv needs a file path, not ''");
    } else if ((arg == "--duration" || arg == "--port" || arg == "--test" || arg == "--seed" ||
                (program.csv && arg == "--csv")) &&
               !has_value) {
      return refuse(argv[0], arg + " needs a value after it");
    } else if (!program.extra || !program.extra(arg)) {
      std::cerr << argv[0] << ": unknown argument '" << arg << "'\n";
      return program.usage(argv[0], 2);
    }
  }
  if (options.port != 0 && !options.live) return refuse(argv[0], "'--port' applies to --live only (add --live)");
  // The seed is the grader's: it names the formula tests' inputs of one grading, so a program
  // takes it only with the graded test it replays (no simulated test draws from it).
  if (options.seed != 0 && options.test.empty())
    return refuse(argv[0], "'--seed' applies to --test only (the replay of a graded test; add --test NAME)");
  if (!options.test.empty() && options.duration_given)
    return refuse(argv[0], "'--duration' does not apply with '--test': a replay lasts as long as the graded run");
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

std::string program_name(const char* argv0) {
  const std::string path = argv0 ? argv0 : "";
  const std::string name = path.substr(path.find_last_of('/') + 1);
  return name.empty() ? "hw2" : name;
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

void start_replay(Options& options, const std::string& problem, double graded_duration) {
  if (options.test.empty()) return;
  options.run.duration = graded_duration;
  std::cout << "replaying the graded test \"" << options.test << "\" of problem " << problem << ": its scenario, "
            << options.run.duration << " s as the grader ran it";
  if (options.seed != 0) std::cout << " (seed " << options.seed << ": the simulated scenarios draw no random input)";
  std::cout << "\n";
}

void print_final(const Options& options, const std::string& quantity, double value, const std::string& unit) {
  if (options.test.empty()) return;
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  std::cout << "final " << quantity << ": " << text << " " << unit << "\n";
}

int no_live(const char* program) {
  std::cerr << program << ": this build has no live lab (--live): install libcpp-httplib-dev (bash scripts/setup.sh "
            << "does) and build again\n";
  return 2;
}

int scenario_usage(const char* program, int code, const std::string& what, double duration, bool live) {
  (code ? std::cerr : std::cout)
      << "usage: " << program << " [--duration SECONDS] [--csv PATH] [--no-plots] [--no-replay]"
      << (live ? " [--live [--port N]]" : "") << "\n"
      << "       [--test NAME [--seed N]]   replay a graded test's run, as the grader's report prints it\n"
      << "  " << what << "\n"
      << "  --duration  simulated seconds (default " << duration << ", at most " << kMaxDuration << ")\n"
      << "  --csv       log file (default out/" << program_name(program) << ".csv in the repository); plots and the 3D replay page are\n"
      << "              written next to it, named after it (docs/visuals.md)\n"
      << "  --no-plots, --no-replay  skip those pictures\n";
  if (live) {
    (code ? std::cerr : std::cout)
        << "  --live      run in real time in the browser, push the arm with the mouse (docs/live.md); until\n"
        << "              Ctrl-C, or --duration simulated seconds. --port N: its port (default: a free one)\n";
  }
  return code;
}

int no_lab(const char* program, const std::string& problem) {
  std::cerr << program << ": problem " << problem << " has no live lab (--live): its folder declares none (LAB in "
            << "problems/" << problem << "/CMakeLists.txt)\n";
  return 2;
}

int guarded(const char* program, const std::function<int()>& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace opspace::programs
