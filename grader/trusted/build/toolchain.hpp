/// @file toolchain.hpp
/// How this build compiles and links a runner, as grader/CMakeLists.txt writes it
/// (runner-toolchain.txt, one KEY=VALUE per line), with its fingerprint, part of every cached
/// runner's key (runner_build.hpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace opspace::grading {

/// How CMake compiles and links a runner (the file grader/CMakeLists.txt generates).
struct Toolchain {
  std::vector<std::string> compile;  ///< compiler and flags; the grader adds -c FILE -o OBJECT
  std::vector<std::string> link;     ///< compiler and flags; the grader adds OBJECT, the inputs, -o
  /// Per problem key: the link inputs after the object (the runner loop, the library).
  std::vector<std::pair<std::string, std::vector<std::string>>> inputs;
  std::vector<std::string> include_roots;  ///< folders a student's file may include from
  std::vector<std::string> headers;        ///< what the compiler must see of this build (read-only)
  std::vector<std::string> archives;       ///< what the linker must see of this build (read-only)
  std::string nm;                          ///< the nm program
  /// The compiler's LTO plugin, which nm is told to load instead of every plugin of
  /// bfd-plugins/ (10 ms instead of 70 where clang's LLVMgold is there); empty: nm as it is.
  std::string nm_plugin;
  /// nm and its options before the grader's: {nm} or {nm, --plugin, nm_plugin}.
  std::vector<std::string> nm_command() const;
  /// Changes when any of the above changes, the grader is rebuilt, or a file under `headers`
  /// is added, removed or touched.
  std::string fingerprint;
};

/// Reads the toolchain file. Throws std::runtime_error naming the file and line on bad input.
Toolchain load_toolchain(const std::string& path);

}  // namespace opspace::grading
