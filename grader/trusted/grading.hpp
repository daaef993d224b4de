/// @file grading.hpp
/// A graded test: a sentence, points, and a body that inspects the student's functions
/// through a Check, which records what was expected, what was computed and what it means.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "api.hpp"

namespace opspace::grading {

/// Collects the findings of one graded test. A test earns fraction() of its points.
class Check {
 public:
  /// Passes if |computed - expected| <= tol * max(1, |expected|) entry-wise (max norm).
  /// On failure records "what: expected E, computed C" and the physical `meaning`.
  bool near(const std::string& what, const Eigen::Ref<const Eigen::MatrixXd>& expected,
            const Eigen::Ref<const Eigen::MatrixXd>& computed, double tol,
            const std::string& meaning);
  /// Scalar version of near().
  bool near(const std::string& what, double expected, double computed, double tol,
            const std::string& meaning);
  /// Passes if `condition`; otherwise records `message`.
  bool that(bool condition, const std::string& message);
  /// A measured quantity that should stay at or below `bound`. Partial credit rule: at or
  /// below the bound earns full credit, up to twice the bound half, beyond that nothing.
  /// `what` names the quantity with its unit; values are printed with `unit_scale` applied.
  bool at_most(const std::string& what, double measured, double bound, const std::string& meaning,
               double unit_scale = 1.0, const std::string& unit = "");
  /// A measured quantity that should reach `bound`: full credit at or above it, half from
  /// bound / 2, nothing below (the mirror image of at_most()).
  bool at_least(const std::string& what, double measured, double bound, const std::string& meaning,
                double unit_scale = 1.0, const std::string& unit = "");
  /// Caps the test's credit at `fraction` (partial credit for a measured quantity).
  void credit_at_most(double fraction, const std::string& message);

  double fraction() const { return fraction_; }  ///< share of the points earned, 0 to 1
  const std::vector<std::string>& findings() const { return findings_; }  ///< what failed, in order

 private:
  void fail(const std::string& message);
  double fraction_ = 1.0;
  std::vector<std::string> findings_;
};

/// One graded test of a problem.
struct GradedTest {
  std::string name;     ///< what a passing implementation does, as a sentence
  double points = 0.0;  ///< what a passing implementation earns
  std::string hint;     ///< how to think about a failure
  std::function<void(const Hw2Api&, Check&)> body;  ///< runs the checks on the functions of the api
};

/// What one graded test earned.
struct TestResult {
  const GradedTest* test = nullptr;  ///< the test, owned by its Problem
  double score = 0.0;                ///< points earned: Check::fraction() times the test's points
  std::vector<std::string> findings;  ///< failed checks, or what the student code threw
  /// The student's code crashed, timed out, exited or sent garbage during this test: the
  /// findings say what happened, and no formula hint applies.
  bool interrupted = false;
  /// A known mistake was named for this test: the likely-mistake line replaces the hint.
  bool diagnosed = false;
  std::string printed;  ///< what the student's code printed during the test (sanitized, cut)
};

class RunnerProcess;
struct Mistake;

/// Runs `tests` against `api`; a test whose body throws earns 0 and reports the exception.
/// With a `runner` (the grader), each test gets `timeout` seconds for all its requests, and a
/// runner that fails is started again for the next test. With a `catalogue` (mistakes.hpp), a
/// failed test whose answers one known mistake reproduces names it ("likely mistake: ...").
std::vector<TestResult> run_tests(const std::vector<GradedTest>& tests, const Hw2Api& api,
                                  RunnerProcess* runner = nullptr, double timeout = 0.0,
                                  const std::vector<Mistake>* catalogue = nullptr);

/// The random inputs of a grading run derive from one seed (hw2-grade prints it; --seed
/// replays it). 0, the default, gives the fixed inputs the suite's own tests use.
void set_run_seed(std::uint64_t seed);
/// The seed of the run.
std::uint64_t run_seed();
/// The seed of one random stream of a test: `salt` itself when the run seed is 0.
unsigned seed_for(unsigned salt);

/// "[[a, b], [c, d]]", six significant digits: how matrices appear in findings.
std::string format(const Eigen::Ref<const Eigen::MatrixXd>& M);

}  // namespace opspace::grading
