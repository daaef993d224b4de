/// @file grading.hpp
/// A graded test: a sentence, points, and a body that inspects the student's functions
/// through a Check, which records what was expected, what was computed and what it means.
#pragma once

#include <Eigen/Core>
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
  /// Caps the test's credit at `fraction` (partial credit for a measured quantity).
  void credit_at_most(double fraction, const std::string& message);

  double fraction() const { return fraction_; }
  const std::vector<std::string>& findings() const { return findings_; }

 private:
  void fail(const std::string& message);
  double fraction_ = 1.0;
  std::vector<std::string> findings_;
};

/// One graded test of a problem.
struct GradedTest {
  std::string name;     ///< what a passing implementation does, as a sentence
  double points = 0.0;
  std::string hint;     ///< how to think about a failure
  std::function<void(const Hw2Api&, Check&)> body;
};

/// What one graded test earned.
struct TestResult {
  const GradedTest* test = nullptr;
  double score = 0.0;
  std::vector<std::string> findings;  ///< failed checks, or what the student code threw
};

/// Runs `tests` against `api`; a test whose body throws earns 0 and reports the exception.
std::vector<TestResult> run_tests(const std::vector<GradedTest>& tests, const Hw2Api& api);

/// "[[a, b], [c, d]]", six significant digits: how matrices appear in findings.
std::string format(const Eigen::Ref<const Eigen::MatrixXd>& M);

}  // namespace opspace::grading
