/// @file report.hpp
/// Grading a problem and printing the score table a student reads.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "judge/graded_suite.hpp"

namespace opspace::grading {

/// The results of one problem's tests, with the points earned and available.
struct ProblemResult {
  const Problem* problem = nullptr;  ///< the problem graded
  std::vector<TestResult> results;   ///< one per test, in the problem's order
  double score = 0.0;                ///< sum of the results' scores
  double max_score = 0.0;            ///< sum of the tests' points
  std::string failure;   ///< empty, or why the problem could not be graded (its file does not compile)
  bool grader_fault = false;  ///< `failure` is the grader's own (fault.hpp), not the submission's
  std::string warnings;  ///< the compiler's warnings on the problem's file (shown, never fatal)
  std::vector<std::string> notes;  ///< other things the student should know (oracle calls)
};

/// Points as the report and the grader's notes write them ("%g": 3, 2.5, 0.25).
std::string format_points(double value);

/// Runs every test of `problem` against `api`.
ProblemResult grade(const Problem& problem, const Hw2Api& api);

/// Whether the student is kept from seeing `test` of `problem` (--hidden): its name, with the
/// problem's key in front ("1b iii. in simulation ..."), contains one of `hidden`.
bool is_hidden(const ProblemResult& problem, const TestResult& test, const std::vector<std::string>& hidden);

/// What the student sees of a problem's points: the shown tests' score and maximum, and how
/// many tests are hidden with how many points (never what they earned).
struct ShownScore {
  double score = 0.0;
  double max_score = 0.0;
  int hidden_tests = 0;
  double hidden_points = 0.0;
};
ShownScore shown_score(const ProblemResult& problem, const std::vector<std::string>& hidden);

/// "PASS", "PART" (some credit) or "FAIL".
std::string status(const TestResult& r);

/// The command that runs simulated test `test`'s scenario in its program, as the grader ran it
/// ("bash scripts/run hw2-p1 3 --test \"...\" --seed 42"; no --seed when `seed` is 0); empty
/// for a test of formulas.
std::string replay_command(const GradedTest& test, std::uint64_t seed);

/// Prints one block per problem (each test's status, points, findings and hint, and for a failed
/// simulated test the command that replays it with `seed`), the score per problem and the
/// total. The tests of `hidden` are left out, and every score counts the shown tests alone: the
/// printed report is the student's (scripts/regrade's report.txt); the whole grade is in
/// results.json and the gradebook.
void print_report(std::ostream& out, const std::vector<ProblemResult>& problems,
                  const std::vector<std::string>& hidden = {}, std::uint64_t seed = 0);

}  // namespace opspace::grading
