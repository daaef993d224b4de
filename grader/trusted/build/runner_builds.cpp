#include "build/runner_builds.hpp"

#include <algorithm>
#include <cstddef>
#include <exception>
#include <iostream>
#include <thread>

#include "common/at_once.hpp"

namespace opspace::grading {

std::string exercise_file(const std::string& key) { return "p" + key + ".cpp"; }

std::vector<BuiltRunner> build_runners(const std::vector<std::string>& keys, const Toolchain& toolchain,
                                       const std::string& exercises, const BuildSettings& settings) {
  std::vector<BuiltRunner> built(keys.size());
  at_once(keys.size(), std::max(1u, std::thread::hardware_concurrency()), [&](std::size_t i) {
    const std::string file = exercise_file(keys[i]);
    try {
      built[i] = build_runner(toolchain, keys[i], exercises + "/" + file, "exercises/" + file, settings);
    } catch (const std::exception& e) {
      built[i].error = std::string("the grader could not build the runner: ") + e.what();
      built[i].fault = Fault::grader;
    }
  });
  return built;
}

void print_built(const std::vector<std::string>& keys, const std::vector<BuiltRunner>& built) {
  for (std::size_t i = 0; i < keys.size(); ++i) {
    std::cerr << "  exercises/" << exercise_file(keys[i]) << ": "
              << (!built[i].ok ? "not built (the report says why)"
                  : built[i].cached ? "unchanged since it was last built by this grader: its runner is reused"
                                    : "compiled")
              << "\n";
  }
}

}  // namespace opspace::grading
