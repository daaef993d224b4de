/// @file runner_build.hpp
/// Building a problem's runner from one exercise file, each stage in the sandbox and seeing only
/// what it needs (docs/grader.md, "What each stage sees"): compile the file (a copy the grader
/// wrote, read-only, with the headers and never an archive; the student's warnings shown, never
/// fatal), check what it included, link the object (the grader's copy) with that problem's
/// runner loop and the library, and list which of the library's answers the runner holds
/// (library_answers.hpp). A failure costs that problem only and is reported with the file, the
/// line and the compiler's first error, and with who caused it (fault.hpp).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "build/build_tool.hpp"
#include "build/library_answers.hpp"
#include "build/toolchain.hpp"
#include "common/fault.hpp"
#include "sandbox/sandbox.hpp"

namespace opspace::grading {

/// The outcome of building one problem's runner.
struct BuiltRunner {
  bool ok = false;
  std::string binary;                 ///< the runner (in the cache), when ok
  std::vector<std::string> runtime;   ///< the files it needs to start (elf_files.hpp)
  std::string error;                  ///< why not: "exercises/p1b.cpp:12: error: ..."
  Fault fault = Fault::none;          ///< who caused `error`
  std::string warnings;               ///< the compiler's warnings, cut short
  std::vector<std::string> answers;   ///< library answers the runner holds: "opspace::pp::mass_matrix"
  std::vector<Oracle> called;         ///< the oracles they belong to
  bool cached = false;                ///< reused from an earlier build of the same inputs
};

/// Builds problem `key`'s runner from `source` (shown to the student as `shown_as`).
BuiltRunner build_runner(const Toolchain& toolchain, const std::string& key, const std::string& source,
                         const std::string& shown_as, const BuildSettings& settings);

/// What the grader reads of nm's list of a file's symbols: a runner's lists 5-15 kB (--gc-sections).
constexpr std::size_t kMaxSymbolList = 64u << 20;

/// nm's list of the symbols of `file`, or why not and whose fault that is.
struct SymbolList {
  std::vector<std::string> names;
  std::string error;
  Fault fault = Fault::none;
};

/// Lists the symbols of `file` with `nm` (the program and its first options,
/// Toolchain::nm_command; `which`: --defined-only, --undefined-only) in the sandbox, writing in
/// `work`. The list is kept whole or not at all, since a cut one could hide
/// a library answer: one over `max_size` is the submission's ("exercises/p1a.cpp makes the
/// symbol list over the 64 MiB the grader reads: ..."), as are nm's failure and time-out on
/// its object; nm that cannot be started is the grader's. `what` names the list for the
/// student: "the names it refers to".
SymbolList list_symbols(const std::vector<std::string>& nm, const std::string& which, const std::string& file,
                        const std::string& work, const BuildSettings& settings, const std::string& shown_as,
                        const std::string& what, std::size_t max_size = kMaxSymbolList);

}  // namespace opspace::grading
