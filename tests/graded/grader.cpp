#include "grader.hpp"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>

#include "suite.hpp"

namespace opspace::grading {

namespace {

int usage(std::ostream& out, const char* program, int code) {
  out << "usage: " << program << " [--problem KEY] [--timeout SECONDS] [--gradescope FILE] [--junit FILE]\n"
      << "          [--hidden TEXT]... [--no-isolation]\n"
      << "  --problem     grade one problem only (";
  bool first = true;
  for (const Problem& p : graded_suite()) {
    out << (first ? "" : ", ") << p.key;
    first = false;
  }
  out << ")\n"
      << "  --timeout     time limit of each problem's process, in seconds (default 60)\n"
      << "  --gradescope  also write Gradescope's results.json to FILE\n"
      << "  --junit       also write JUnit XML to FILE\n"
      << "  --hidden      mark the tests whose name contains TEXT hidden in results.json\n"
      << "  --no-isolation  grade in this process (for debuggers; a crash then ends grading)\n"
      << "Exit code 0 whenever grading ran, whatever the score.\n";
  return code;
}

template <typename Writer>
bool write_file(const std::string& path, const char* what, Writer writer) {
  std::ofstream file(path);
  if (file) writer(file);
  if (!file) {
    std::cerr << "hw2-grade: cannot write the " << what << " file " << path << "\n";
    return false;
  }
  std::cout << what << ": " << path << "\n";
  return true;
}

}  // namespace

int grader_main(int argc, char** argv, const Hw2Api& api, const std::string& graded_library) {
  GraderOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--help" || arg == "-h") return usage(std::cout, argv[0], 0);
    if (arg == "--problem" && has_value) {
      options.only_problem = argv[++i];
    } else if (arg == "--timeout" && has_value) {
      char* end = nullptr;
      options.timeout = std::strtod(argv[++i], &end);
      if (*end != '\0' || !(options.timeout > 0.0)) {
        std::cerr << argv[0] << ": --timeout needs a positive number of seconds\n";
        return 2;
      }
    } else if (arg == "--gradescope" && has_value) {
      options.gradescope_path = argv[++i];
    } else if (arg == "--junit" && has_value) {
      options.junit_path = argv[++i];
    } else if (arg == "--hidden" && has_value) {
      options.hidden.push_back(argv[++i]);
    } else if (arg == "--no-isolation") {
      options.isolate = false;
    } else {
      std::cerr << argv[0] << ": unknown or incomplete argument '" << arg << "'\n";
      return usage(std::cerr, argv[0], 2);
    }
  }

  const auto start = std::chrono::steady_clock::now();
  const std::vector<Problem> suite = graded_suite();
  std::vector<ProblemResult> results;
  std::cout << "opspace grader: problem set 2, " << graded_library << "\n" << std::flush;
  for (const Problem& problem : suite) {
    if (!options.only_problem.empty() && problem.key != options.only_problem) continue;
    std::cerr << "grading problem " << problem.key << "...\n";
    results.push_back(options.isolate ? grade_isolated(problem, api, options.timeout) : grade(problem, api));
  }
  if (results.empty()) {
    std::cerr << argv[0] << ": no problem '" << options.only_problem << "'\n";
    return usage(std::cerr, argv[0], 2);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  print_report(std::cout, results);

  bool written = true;
  if (!options.gradescope_path.empty()) {
    written &= write_file(options.gradescope_path, "results.json",
                          [&](std::ostream& out) { write_gradescope(out, results, seconds, options.hidden); });
  }
  if (!options.junit_path.empty()) {
    written &= write_file(options.junit_path, "JUnit XML", [&](std::ostream& out) { write_junit(out, results, seconds); });
  }
  return written ? 0 : 1;
}

}  // namespace opspace::grading
