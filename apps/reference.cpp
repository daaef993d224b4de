// hw2-reference: the reference runs that the programs and the docs quote. It runs every
// problem's scenario with solutions/ at the programs' default durations, then
//   hw2-reference generate HEADER FRAGMENTS
//       writes HEADER (reference_runs.hpp: the Summary of each run, which the hw2-p* programs
//       print beside their own) and FRAGMENTS (the docs' tables of the reference runs);
//   hw2-reference docs check|write DOCS_DIR FRAGMENTS
//       compares (ctest) or replaces the text between "<!-- generated: NAME ..." and
//       "<!-- end generated: NAME -->" in DOCS_DIR/*.md and in the problems' guides beside it,
//       DOCS_DIR/../problems/*/guide.md, with fragment NAME of FRAGMENTS.
// The build runs `generate` (apps/CMakeLists.txt); `cmake --build build/release --target
// refresh-docs` runs `docs write`.
// The files: this one (the runs and the command line), reference_header.cpp,
// reference_fragments.cpp, reference_docs.cpp; reference.hpp what they share.
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <opspace/hw2/p1b.hpp>
#include <opspace/hw2/p2.hpp>
#include <opspace/hw2/p3.hpp>
#include <opspace/hw2/p4.hpp>
#include <problems/1b/scenario.hpp>
#include <problems/2/scenario.hpp>
#include <problems/3/scenario.hpp>
#include <problems/4/scenario.hpp>

#include "reference.hpp"

namespace hw2_reference {

namespace {

Runs run_all() {
  Runs runs;
  sc::RunOptions options;
  options.duration = p1b::kDefaultDuration;
  for (Part part : kParts) runs.p1b[part] = p1b::run(part, &opspace::hw2::p1b::control, options);
  options.duration = p2::kDefaultDuration;
  runs.p2 = p2::run(&opspace::hw2::p2::control, &opspace::hw2::p2::desired_acceleration, options);
  options.duration = p3::kDefaultDuration;
  runs.p3 = p3::run(&opspace::hw2::p3::control, options);
  options.duration = p4::kDuration;
  for (Target target : kTargets) {
    runs.p4[target] = p4::run(target, &opspace::hw2::p4::control, options);
    runs.p4_plain[target] = p4::run_plain(target, options);
  }
  for (const auto& [part, r] : runs.p1b) {
    if (!r.failure.empty()) throw std::runtime_error(p1b::describe(part) + " stopped early: " + r.failure);
  }
  for (const std::string* failure : {&runs.p2.failure, &runs.p3.failure, &runs.p4[Target::kAlongZ0].failure,
                                     &runs.p4[Target::kAlongY0].failure}) {
    if (!failure->empty()) throw std::runtime_error("a reference run stopped early: " + *failure);
  }
  return runs;
}

int usage() {
  std::cerr << "usage: hw2-reference generate HEADER FRAGMENTS\n"
               "       hw2-reference docs check|write DOCS_DIR FRAGMENTS\n";
  return 2;
}

}  // namespace

}  // namespace hw2_reference

int main(int argc, char** argv) {
  using namespace hw2_reference;
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.size() == 3 && args[0] == "generate") {
      for (const std::string& path : {args[1], args[2]}) {
        std::filesystem::create_directories(std::filesystem::path(path).parent_path());
      }
      const Runs runs = run_all();
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
