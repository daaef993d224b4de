/// @file results_files.hpp
/// The files a grading writes beside its printed report, each as the command line asks:
/// Gradescope's results.json, PrairieLearn's, JUnit XML and the report's page. Each is written
/// through a temporary file and a rename, so that a reader sees the old file or the whole new one.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "judge/problem_result.hpp"

namespace opspace::grading {

/// Which files to write (an empty path: not that one), and what they show.
struct ResultsFiles {
  std::string gradescope;            ///< results.json (--gradescope)
  std::string prairielearn;          ///< PrairieLearn's results.json (--prairielearn)
  std::string junit;                 ///< JUnit XML (--junit)
  std::string html;                  ///< the report's page (--html)
  std::vector<std::string> hidden;   ///< tests whose name contains one of these are hidden
  std::string hidden_as = "after_published";  ///< their visibility in results.json
  std::string gradescope_format = "html";     ///< results.json's tests' output_format
  std::uint64_t seed = 0;            ///< the grading's seed
  bool unprotected = false;          ///< the code graded ran without the whole sandbox
};

/// Writes the files `files` names, each said on stdout ("results.json: PATH"; the page: "open
/// PATH"). False, said on stderr, if one could not be written.
bool write_results_files(const ResultsFiles& files, const std::vector<ProblemResult>& results, double seconds);

}  // namespace opspace::grading
