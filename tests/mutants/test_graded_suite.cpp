// The graded suite must discriminate: full marks for the reference solutions, and each
// known-wrong implementation loses exactly the tests aimed at it, no fewer and no more.
// (That the untouched stubs score 0 is checked on the real hw2-grade program: see
// tests/graded/check_stubs.cmake.)
#include <doctest/doctest.h>

#include <set>
#include <string>

#include "linked_api.hpp"
#include "mutants.hpp"
#include "report.hpp"
#include "suite.hpp"

namespace grading = opspace::grading;

namespace {

std::set<std::string> failed_tests(const grading::Hw2Api& api) {
  std::set<std::string> failed;
  for (const grading::Problem& problem : grading::graded_suite()) {
    for (const grading::TestResult& r : grading::run_tests(problem.tests, api)) {
      if (r.score < r.test->points) failed.insert(r.test->name);
    }
  }
  return failed;
}

std::string join(const std::set<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += "\n    " + n;
  return out.empty() ? " (none)" : out;
}

}  // namespace

TEST_CASE("the reference solutions earn full marks on every graded test") {
  for (const grading::Problem& problem : grading::graded_suite()) {
    const grading::ProblemResult result = grading::grade(problem, grading::linked_api());
    for (const grading::TestResult& r : result.results) {
      std::string findings;
      for (const std::string& f : r.findings) findings += "\n    " + f;
      INFO("problem " << problem.key << ": " << r.test->name << findings);
      CHECK(r.score == r.test->points);
    }
  }
}

TEST_CASE("each known-wrong implementation loses exactly the tests aimed at it") {
  std::uint64_t identity = 100;
  for (const opspace::mutants::Mutant& mutant : opspace::mutants::all_mutants()) {
    grading::Hw2Api api = grading::linked_api();
    mutant.apply(api);
    api.identity = ++identity;  // its own simulated runs
    const std::set<std::string> expected(mutant.caught_by.begin(), mutant.caught_by.end());
    const std::set<std::string> failed = failed_tests(api);
    INFO("mistake: " << mutant.mistake << "\n  tests that should fail:" << join(expected)
                     << "\n  tests that failed:" << join(failed));
    CHECK(failed == expected);
  }
}

TEST_CASE("every graded test names what it checks and carries points and a hint") {
  for (const grading::Problem& problem : grading::graded_suite()) {
    std::set<std::string> names;
    for (const grading::GradedTest& test : problem.tests) {
      INFO("problem " << problem.key << ": " << test.name);
      CHECK(test.points > 0);
      CHECK(!test.hint.empty());
      CHECK(names.insert(test.name).second);  // unique, so that a mutant's target is unambiguous
    }
  }
}
