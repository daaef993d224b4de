/// @file runner_builds.hpp
/// The build stage of a grading: every chosen problem's runner built from its exercise file,
/// several at once (one compiler per core), and a line for each.
#pragma once

#include <string>
#include <vector>

#include "build/runner_build.hpp"

namespace opspace::grading {

/// The exercise file of problem `key`: "p1b.cpp".
std::string exercise_file(const std::string& key);

/// The runners of problems `keys`, from their files in `exercises`, in the same order; a runner
/// the grader could not build says so (Fault::grader).
std::vector<BuiltRunner> build_runners(const std::vector<std::string>& keys, const Toolchain& toolchain,
                                       const std::string& exercises, const BuildSettings& settings);

/// One line per exercise file, on stderr: built, reused from the cache, or not built.
void print_built(const std::vector<std::string>& keys, const std::vector<BuiltRunner>& built);

}  // namespace opspace::grading
