#include "report/results_files.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <system_error>

#include "report/autograder_output.hpp"
#include "report/prairielearn_output.hpp"
#include "report/report_html.hpp"

namespace opspace::grading {

namespace fs = std::filesystem;

namespace {

// Writes through a temporary file and a rename: a reader sees the old file or the whole new one.
template <typename Writer>
bool write_file(const std::string& path, const char* what, Writer writer) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream file(temporary);
    if (file) writer(file);
    if (!file) {
      std::cerr << "hw2-grade: cannot write the " << what << " file " << path << "\n";
      return false;
    }
  }
  std::error_code ec;
  fs::rename(temporary, path, ec);
  if (ec) {
    std::cerr << "hw2-grade: cannot write the " << what << " file " << path << ": " << ec.message() << "\n";
    return false;
  }
  std::cout << what << ": " << path << "\n";
  return true;
}

// `path` relative to the current folder when it lies below it ("out/grade/report.html").
std::string shown_path(const std::string& path) {
  std::error_code ec;
  const fs::path full = fs::weakly_canonical(fs::absolute(path, ec), ec);
  const fs::path here = fs::weakly_canonical(fs::current_path(ec), ec);
  if (ec) return path;
  const auto [f, h] = std::mismatch(full.begin(), full.end(), here.begin(), here.end());
  return h == here.end() ? full.lexically_relative(here).string() : full.string();
}

}  // namespace

bool write_results_files(const ResultsFiles& files, const std::vector<ProblemResult>& results, double seconds) {
  bool written = true;
  if (!files.gradescope.empty()) {
    written &= write_file(files.gradescope, "results.json",
                          [&](std::ostream& out) {
                            write_gradescope(out, results, seconds,
                                             {files.hidden, files.hidden_as, files.seed, files.gradescope_format,
                                              files.unprotected});
                          });
  }
  if (!files.prairielearn.empty()) {
    written &= write_file(files.prairielearn, "PrairieLearn's results.json", [&](std::ostream& out) {
      write_prairielearn(out, results, seconds, {files.hidden, files.seed});
    });
  }
  if (!files.junit.empty()) {
    written &= write_file(files.junit, "JUnit XML", [&](std::ostream& out) { write_junit(out, results, seconds); });
  }
  if (!files.html.empty()) {
    std::error_code ec;  // a folder that cannot be made: write_file says the page cannot be written
    fs::create_directories(fs::path(files.html).parent_path(), ec);
    const bool page = write_file(files.html, "the report's page", [&](std::ostream& out) {
      write_html_report(out, results, files.hidden, files.seed);
    });
    if (page) std::cout << "open " << shown_path(files.html) << "\n";
    written &= page;
  }
  return written;
}

}  // namespace opspace::grading
