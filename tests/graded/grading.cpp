#include "grading.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <sstream>

namespace opspace::grading {

std::string format(const Eigen::Ref<const Eigen::MatrixXd>& M) {
  std::ostringstream s;
  s.precision(6);
  if (M.size() == 1) {
    s << M(0, 0);
    return s.str();
  }
  const bool vector = M.cols() == 1 || M.rows() == 1;
  s << "[";
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    if (!vector) s << (i ? ", [" : "[");
    for (Eigen::Index j = 0; j < M.cols(); ++j) {
      if (i + j > 0 && (vector || j > 0)) s << ", ";
      s << M(i, j);
    }
    if (!vector) s << "]";
  }
  s << "]";
  if (M.cols() == 1 && M.rows() > 1) s << "^T";
  return s.str();
}

void Check::fail(const std::string& message) {
  fraction_ = 0.0;
  findings_.push_back(message);
}

bool Check::near(const std::string& what, const Eigen::Ref<const Eigen::MatrixXd>& expected,
                 const Eigen::Ref<const Eigen::MatrixXd>& computed, double tol,
                 const std::string& meaning) {
  const bool same_shape = expected.rows() == computed.rows() && expected.cols() == computed.cols();
  bool ok = same_shape && computed.allFinite();
  if (ok) {
    const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
    ok = (computed - expected).cwiseAbs().maxCoeff() <= tol * scale;
  }
  if (!ok) {
    fail(what + ": expected " + format(expected) + ", computed " + format(computed) +
         (meaning.empty() ? "" : ". " + meaning));
  }
  return ok;
}

bool Check::near(const std::string& what, double expected, double computed, double tol,
                 const std::string& meaning) {
  return near(what, Eigen::Matrix<double, 1, 1>(expected), Eigen::Matrix<double, 1, 1>(computed),
              tol, meaning);
}

bool Check::that(bool condition, const std::string& message) {
  if (!condition) fail(message);
  return condition;
}

namespace {

std::string value(double v, double scale, const std::string& unit) {
  std::ostringstream s;
  s.precision(4);
  s << v * scale << (unit.empty() ? "" : " " + unit);
  return s.str();
}

}  // namespace

bool Check::at_most(const std::string& what, double measured, double bound, const std::string& meaning,
                    double unit_scale, const std::string& unit) {
  if (std::isfinite(measured) && measured <= bound) return true;
  const std::string finding = what + ": expected at most " + value(bound, unit_scale, unit) + ", measured " +
                              value(measured, unit_scale, unit);
  if (std::isfinite(measured) && measured <= 2.0 * bound) {
    credit_at_most(0.5, finding + " (within twice the bound: half credit). " + meaning);
  } else {
    fail(finding + ". " + meaning);
  }
  return false;
}

bool Check::at_least(const std::string& what, double measured, double bound, const std::string& meaning,
                     double unit_scale, const std::string& unit) {
  if (std::isfinite(measured) && measured >= bound) return true;
  const std::string finding = what + ": expected at least " + value(bound, unit_scale, unit) + ", measured " +
                              value(measured, unit_scale, unit);
  if (std::isfinite(measured) && measured >= 0.5 * bound) {
    credit_at_most(0.5, finding + " (within half the bound: half credit). " + meaning);
  } else {
    fail(finding + ". " + meaning);
  }
  return false;
}

void Check::credit_at_most(double fraction, const std::string& message) {
  fraction_ = std::min(fraction_, std::clamp(fraction, 0.0, 1.0));
  findings_.push_back(message);
}

std::vector<TestResult> run_tests(const std::vector<GradedTest>& tests, const Hw2Api& api) {
  std::vector<TestResult> results;
  results.reserve(tests.size());
  for (const GradedTest& test : tests) {
    TestResult result;
    result.test = &test;
    Check check;
    try {
      test.body(api, check);
      result.score = check.fraction() * test.points;
      result.findings = check.findings();
    } catch (const std::exception& e) {
      result.findings = {std::string("your code threw an exception: ") + e.what()};
    } catch (...) {
      result.findings = {"your code threw an exception that is not a std::exception"};
    }
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace opspace::grading
