// hw2-reference: the reference runs that the programs and the docs quote. It runs each
// problem's reference run (problems/<key>/run/reference.cpp, named REFERENCE in its folder's
// CMakeLists.txt: solutions/ on its scenario at the program's default duration), then
//   hw2-reference generate HEADER FRAGMENTS
//       writes HEADER (reference_runs.hpp: each problem's declarations, which the hw2-p* programs
//       print beside their own values) and FRAGMENTS (the docs' tables of the reference runs);
//   hw2-reference docs check|write DOCS_DIR FRAGMENTS
//       compares (ctest) or replaces the text between "<!-- generated: NAME ..." and
//       "<!-- end generated: NAME -->" in DOCS_DIR/*.md and in the problems' guides beside it,
//       DOCS_DIR/../problems/*/guide.md, with fragment NAME of FRAGMENTS.
// The build runs `generate` (apps/CMakeLists.txt); `cmake --build build/release --target
// refresh-docs` runs `docs write`.
// The files: this one (the loop and the command line), reference_write.cpp, reference_docs.cpp;
// reference.hpp what they share; reference_list.hpp (generated) the problems that have a run.
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "opspace/programs/reference_text.hpp"

#include "reference.hpp"
#include "reference_list.hpp"

namespace programs = opspace::programs;

// Each problem's reference run: programs::ReferenceText reference_run_<key>() (problems/<key>/run/reference.cpp).
#define OPSPACE_DECLARE_REFERENCE_RUN(key) programs::ReferenceText reference_run_##key();
OPSPACE_REFERENCE_RUNS(OPSPACE_DECLARE_REFERENCE_RUN)
#undef OPSPACE_DECLARE_REFERENCE_RUN

namespace opspace::programs {

namespace {

/// Every problem's reference run, in problems.txt's order.
std::vector<programs::ReferenceText> run_all() {
  std::vector<programs::ReferenceText> runs;
#define OPSPACE_RUN_REFERENCE(key) runs.push_back(reference_run_##key());
  OPSPACE_REFERENCE_RUNS(OPSPACE_RUN_REFERENCE)
#undef OPSPACE_RUN_REFERENCE
  return runs;
}

int usage() {
  std::cerr << "usage: hw2-reference generate HEADER FRAGMENTS\n"
               "       hw2-reference docs check|write DOCS_DIR FRAGMENTS\n";
  return 2;
}

}  // namespace

}  // namespace opspace::programs

int main(int argc, char** argv) {
  using namespace opspace::programs;
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.size() == 3 && args[0] == "generate") {
      for (const std::string& path : {args[1], args[2]}) {
        std::filesystem::create_directories(std::filesystem::path(path).parent_path());
      }
      const std::vector<programs::ReferenceText> runs = run_all();
      write_header(runs, args[1]);
      write_fragments(runs, args[2]);
      return 0;
    }
    if (args.size() == 4 && args[0] == "docs" && (args[1] == "check" || args[1] == "write")) {
      return docs(args[1] == "write", args[2], args[3]);
    }
  } catch (const std::exception& e) {
    std::cerr << "hw2-reference: " << e.what() << "\n";
    return 1;
  }
  return usage();
}
