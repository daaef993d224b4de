/// @file grader.hpp
/// The grading command behind hw2-grade: each problem in its own process with a time limit,
/// a score table, and on request Gradescope's results.json and JUnit XML.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "api.hpp"
#include "report.hpp"

namespace opspace::grading {

/// What hw2-grade's command line sets (docs/grader.md).
struct GraderOptions {
  std::string only_problem;         ///< empty: every problem
  double timeout = 60.0;            ///< seconds per problem
  std::string gradescope_path;      ///< results.json, if not empty
  std::string junit_path;           ///< JUnit XML, if not empty
  std::vector<std::string> hidden;  ///< tests whose name contains one of these are hidden
  bool isolate = true;              ///< run each problem in a child process
};

/// Grades `problem` in a child process (fork) that reports each test as it finishes. If the
/// child crashes, is killed or exceeds `timeout`, the finished tests keep their score and the
/// others earn 0 with a message saying what happened.
ProblemResult grade_isolated(const Problem& problem, const Hw2Api& api, double timeout);

/// Gradescope's results.json: score, max_score, execution_time, output, and tests[] with
/// name, score, max_score, status, output and visibility ("hidden" when the test's name
/// contains one of `hidden`, else "visible").
void write_gradescope(std::ostream& out, const std::vector<ProblemResult>& problems, double seconds,
                      const std::vector<std::string>& hidden);

/// JUnit XML: one <testsuite> per problem, one <testcase> per test, <failure> with the findings.
void write_junit(std::ostream& out, const std::vector<ProblemResult>& problems, double seconds);

/// The whole command: parses argv, grades, prints, writes the requested files. Returns the
/// exit code: 0 when grading ran (whatever the score), 2 for a bad command line, 1 when an
/// output file cannot be written.
int grader_main(int argc, char** argv, const Hw2Api& api, const std::string& graded_library);

}  // namespace opspace::grading
