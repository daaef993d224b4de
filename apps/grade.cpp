// hw2-grade: grades the functions linked into this program (exercises/ in hw2-grade,
// solutions/ in hw2-grade-sol) and prints a score table. Exit code 0 whenever grading ran,
// whatever the score; 2 for a bad command line.
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "api.hpp"
#include "report.hpp"
#include "suite.hpp"

namespace {

void usage(std::ostream& out, const char* program) {
  out << "usage: " << program << " [--problem KEY]\n"
      << "  Grades problem set 2; --problem grades one problem only (";
  bool first = true;
  for (const auto& p : opspace::grading::graded_suite()) {
    out << (first ? "" : ", ") << p.key;
    first = false;
  }
  out << ").\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--problem") == 0 && i + 1 < argc) {
      only = argv[++i];
    } else if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
      usage(std::cout, argv[0]);
      return 0;
    } else {
      std::cerr << argv[0] << ": unknown argument '" << argv[i] << "'\n";
      usage(std::cerr, argv[0]);
      return 2;
    }
  }

  const std::vector<opspace::grading::Problem> suite = opspace::grading::graded_suite();
  const opspace::grading::Hw2Api api = opspace::grading::linked_api();
  std::vector<opspace::grading::ProblemResult> results;
  for (const auto& problem : suite) {
    if (only.empty() || problem.key == only) results.push_back(opspace::grading::grade(problem, api));
  }
  if (results.empty()) {
    std::cerr << argv[0] << ": no problem '" << only << "'\n";
    usage(std::cerr, argv[0]);
    return 2;
  }
  std::cout << "opspace grader: problem set 2, " << OPSPACE_GRADED_LIBRARY << "\n";
  opspace::grading::print_report(std::cout, results);
  return 0;
}
