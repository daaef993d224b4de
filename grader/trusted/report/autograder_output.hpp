/// @file autograder_output.hpp
/// The results files of an autograder: Gradescope's results.json and JUnit XML, and what they
/// share with PrairieLearn's (prairielearn_output.hpp): a test's feedback beside its pictures, a
/// figure's caption, the grader's own faults counted.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "judge/problem_result.hpp"

namespace opspace::grading {

/// What results.json hides, and the grader's record it carries (docs/grader.md).
struct GradescopeSettings {
  std::vector<std::string> hidden;            ///< tests whose "<key> <name>" contains one of these
  std::string hidden_as = "after_published";  ///< their visibility: after_published or after_due_date
  std::uint64_t seed = 0;                     ///< the run's seed (a retry replays it)
  /// The tests' output_format: "html" (each failed simulated test's plot as a PNG, a wrong
  /// matrix as a table, every text escaped) or "text" (the plot as a table of samples).
  std::string format = "html";
  bool unprotected = false;  ///< the code graded ran without the whole sandbox (--unprotected, --no-isolation)
};

/// Gradescope's results.json: score (the whole grade), max_score, execution_time, output (one
/// line per problem counting the tests shown), output_format "text", and tests[] with name,
/// score, max_score, status, output (in `settings.format`) and visibility (`hidden_as` for the hidden tests, else
/// "visible"); every text HTML-escaped. extra_data.grader holds the seed and grader_faults().
void write_gradescope(std::ostream& out, const std::vector<ProblemResult>& problems, double seconds,
                      const GradescopeSettings& settings);


/// A test's feedback as text for a page that shows its pictures beside it: the judged values,
/// findings, hint, replay command, prints and wrong matrix's grid, without the runs' tables (a
/// test not written yet: its one line). Gradescope's html output and PrairieLearn's share it.
std::string feedback_beside_pictures(const TestResult& r, std::uint64_t seed);

/// A figure's caption: the quantity, its unit, which run is which colour, and what is judged.
std::string figure_caption(const RunFigure& f);

/// The tests and problems lost to the grader's own failures (a program it could not start, a
/// runner it could not build), never to the student's code: scripts/regrade grades those again.
/// Counted from ProblemResult::grader_fault and TestResult::grader_fault, never from a text.
int grader_faults(const std::vector<ProblemResult>& problems);

/// JUnit XML: one <testsuite> per problem, one <testcase> per test, <failure> with the findings.
void write_junit(std::ostream& out, const std::vector<ProblemResult>& problems, double seconds);


}  // namespace opspace::grading
