#include "judge/grading.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <sstream>

#include "judge/diagnosis.hpp"
#include "judge/mistakes.hpp"
#include "judge/reference_store.hpp"
#include "run/runner_process.hpp"
#include "run/runs_ahead.hpp"
#include "common/student_text.hpp"

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
  if (!ok && same_shape && expected.size() > 1 && table_.what.empty()) table_ = {what, expected, computed, tol};
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

std::string Judgement::line() const {
  const bool met = std::isfinite(yours) && (upper ? yours <= bound : yours >= bound);
  const std::string theirs = std::isnan(reference) ? "not run" : value(reference, unit_scale, unit);
  const std::string mine = !yours_text.empty() ? yours_text : std::isnan(yours) ? "none" : value(yours, unit_scale, unit);
  return statistic + ": yours " + mine + ", the reference's " + theirs + ", bound " + (upper ? "at most " : "at least ") +
         value(bound, unit_scale, unit) + (met ? ": met" : ": not met");
}

void Check::show(const Judgement& j) {
  judged_.push_back(j.line());
  judgements_.push_back(j);
  for (RunFigure& f : figures_)
    if (!f.draws.empty() && f.draws == j.statistic) f.verdict_yours = j.yours, f.verdict_reference = j.reference;
}

bool Check::judge(const Judgement& j, const std::string& meaning) {
  show(j);
  return j.upper ? at_most(j.statistic, j.yours, j.bound, meaning, j.unit_scale, j.unit)
                 : at_least(j.statistic, j.yours, j.bound, meaning, j.unit_scale, j.unit);
}

void Check::credit_at_most(double fraction, const std::string& message) {
  fraction_ = std::min(fraction_, std::clamp(fraction, 0.0, 1.0));
  findings_.push_back(message);
}

namespace {

std::uint64_t g_run_seed = 0;

TestResult run_test(const GradedTest& test, const Hw2Api& api) {
  TestResult result;
  result.test = &test;
  Check check;
  try {
    test.body(api, check);
    result.score = check.fraction() * test.points;
    result.findings = check.findings();
    result.figures = check.figures();
    result.judged = check.judged();
    result.judgements = check.judgements();
    result.hint_replaced = check.hint_replaced();
    result.table = check.table();
  } catch (const StudentException& e) {
    result.findings = {e.what()};
  } catch (const RunnerFailure& e) {
    result.findings = {e.what()};
    result.interrupted = true;
  } catch (const std::exception& e) {
    result.findings = {std::string("your code threw an exception: ") + student_line(e.what(), 200, std::string(e.what()).size())};
  } catch (...) {
    result.findings = {"your code threw an exception that is not a std::exception"};
  }
  return result;
}

// A mistake named by one test explains the other failed tests it is known to fail (their
// simulated run was shared, so they recorded no calls of their own): say so instead of a hint
// that may blame a term the law test found right.
void carry_diagnoses(const std::vector<Mistake>& catalogue, std::vector<TestResult>& results) {
  for (const Mistake& mistake : catalogue) {
    const std::string line = "likely mistake: " + mistake.what + ".";
    const bool named = std::any_of(results.begin(), results.end(), [&](const TestResult& r) {
      return std::any_of(r.findings.begin(), r.findings.end(), [&](const std::string& f) { return f.rfind(line, 0) == 0; });
    });
    if (!named) continue;
    for (TestResult& r : results) {
      const bool aimed = std::find(mistake.caught_by.begin(), mistake.caught_by.end(), r.test->id) != mistake.caught_by.end();
      if (!aimed || r.diagnosed || r.interrupted || r.not_written || r.score >= r.test->points) continue;
      r.findings.push_back("likely the same mistake as above: " + mistake.what);
      r.diagnosed = true;
      r.mistake = mistake.what;
    }
  }
}

// A mistake named by one test is dropped everywhere when a failed test it is aimed at recorded
// answers it does not give: problem 4's swapped potentials answer as a law without potential
// wherever N^T removes the other target's potential (the law test's random states), and apart
// where it does not (the runs' start, the tip on joint 1's axis).
void drop_contradicted(const std::vector<Mistake>& catalogue, std::vector<TestResult>& results,
                       const std::vector<Recording>& recordings) {
  for (const Mistake& mistake : catalogue) {
    const std::string line = "likely mistake: " + mistake.what + ".";
    const auto names = [&](const std::string& f) { return f.rfind(line, 0) == 0; };
    const bool named = std::any_of(results.begin(), results.end(), [&](const TestResult& r) {
      return std::any_of(r.findings.begin(), r.findings.end(), names);
    });
    if (!named) continue;
    bool contradicted = false;
    for (std::size_t i = 0; i < results.size() && !contradicted; ++i) {
      const TestResult& r = results[i];
      const bool aimed = std::find(mistake.caught_by.begin(), mistake.caught_by.end(), r.test->id) != mistake.caught_by.end();
      if (!aimed || r.interrupted || r.not_written || r.score >= r.test->points) continue;
      contradicted = !explains(mistake, recordings[i]);
    }
    if (!contradicted) continue;
    for (TestResult& r : results) {
      const auto at = std::find_if(r.findings.begin(), r.findings.end(), names);
      if (at == r.findings.end()) continue;
      r.findings.erase(at);
      r.diagnosed = false;
      r.mistake.clear();
    }
  }
}

// The mistake of `catalogue` that diagnose() named in `likely` ("likely mistake: WHAT. ...").
std::string named_mistake(const std::vector<Mistake>& catalogue, const std::string& likely) {
  for (const Mistake& mistake : catalogue)
    if (likely.rfind("likely mistake: " + mistake.what + ".", 0) == 0) return mistake.what;
  return "";
}

}  // namespace

void set_run_seed(std::uint64_t seed) { g_run_seed = seed; }
std::uint64_t run_seed() { return g_run_seed; }

unsigned seed_for(unsigned salt) {
  if (g_run_seed == 0) return salt;
  // splitmix64 of (seed, salt): streams of different tests and runs are unrelated.
  std::uint64_t z = g_run_seed + 0x9e3779b97f4a7c15ull * (salt + 1ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return static_cast<unsigned>(z ^ (z >> 31));
}

std::vector<TestResult> run_tests(const std::vector<GradedTest>& tests, const Hw2Api& api, RunnerProcess* runner,
                                  double timeout, const std::vector<Mistake>* catalogue) {
  std::vector<TestResult> results;
  results.reserve(tests.size());
  std::vector<Recording> recordings;  // each test's, for drop_contradicted()
  // The calls recorded so far in this problem's tests: some all zero, some not. A test that
  // recorded none judged runs an earlier test made (runs are made once and shared).
  bool zeros_seen = false, answers_seen = false;
  for (const GradedTest& test : tests) {
    if (runner) {
      const auto budget = std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(timeout));
      runner->begin_test(std::chrono::steady_clock::now() + budget, timeout);
    }
    Recording recording;
    TestResult result;
    {
      // Where a run made ahead by a second runner is given (runs_ahead.hpp).
      TestInProgress in_progress(runner, catalogue ? &recording : nullptr);
      result = catalogue ? run_test(test, recorded(api, recording)) : run_test(test, api);
    }
    if (runner) {
      // A failure of the runner is what happened, whatever the checks concluded from it.
      if (!runner->failure().empty()) {
        result.score = 0.0;
        result.findings = {runner->failure() + " during this test"};
        result.interrupted = true;
      }
      const Printed printed = runner->end_test();
      if (printed.total > 0) result.printed = student_block(printed.text, RunnerProcess::kMaxPrinted, printed.total);
    }
    const bool all_zero = not_written_yet(recording);
    const bool failed = catalogue && result.score < test.points && !result.interrupted;
    if (failed && (all_zero || (recording.calls.empty() && zeros_seen && !answers_seen))) {
      // Short enough for one line of Gradescope's page.
      result.findings.push_back(all_zero ? "not written yet: every value your code returned in this test is zero, as the "
                                           "stub's are: fill in its FILL ME IN"
                                         : "not written yet: every value your code returned in the run this test judges "
                                           "is zero: fill in its FILL ME IN");
      result.not_written = true;
    } else if (catalogue && result.score < test.points && !result.interrupted) {
      const std::string likely = diagnose(*catalogue, test.id, recording);
      if (!likely.empty()) {
        result.findings.push_back(likely);
        result.diagnosed = true;
        result.mistake = named_mistake(*catalogue, likely);
      }
    }
    // After the runner's part of the test: the reference's runs are the grader's own work.
    attach_references(result.figures, result.score < test.points);
    results.push_back(std::move(result));
    if (!recording.calls.empty()) (all_zero ? zeros_seen : answers_seen) = true;
    if (catalogue) recordings.push_back(std::move(recording));
  }
  if (catalogue) {
    drop_contradicted(*catalogue, results, recordings);
    carry_diagnoses(*catalogue, results);
  }
  return results;
}

}  // namespace opspace::grading
