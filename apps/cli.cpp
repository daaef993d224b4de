#include "cli.hpp"

#include <cstdlib>
#include <exception>

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

int guarded(const char* program, const std::function<int()>& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace cli
