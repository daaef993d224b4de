/// @file report.hpp
/// The score table a student reads, printed from the problems' results (judge/problem_result.hpp),
/// and what the other reports share of it: which tests are hidden, a test's status, its replay.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "judge/problem_result.hpp"
#include "sandbox/sandbox.hpp"

namespace opspace::grading {

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

/// The lines under the report: the times, the seed that replays the inputs, and what of the
/// sandbox did not hold where a runner started (`started`: `protections` are its).
void print_footer(std::ostream& out, double build_seconds, double grading_seconds, std::uint64_t seed, bool isolate,
                  bool started, const Protections& protections);

}  // namespace opspace::grading
