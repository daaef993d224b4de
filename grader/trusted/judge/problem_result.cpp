#include "judge/problem_result.hpp"

#include <cstdio>

namespace opspace::grading {

std::string format_points(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

ProblemResult grade(const Problem& problem, const Hw2Api& api) {
  ProblemResult out;
  out.problem = &problem;
  out.results = run_tests(problem.tests, api);
  for (const TestResult& r : out.results) {
    out.score += r.score;
    out.max_score += r.test->points;
  }
  return out;
}

}  // namespace opspace::grading
