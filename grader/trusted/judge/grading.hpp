/// @file grading.hpp
/// A graded test: a sentence, points, and a body that inspects the student's functions
/// through a Check, which records what was expected, what was computed and what it means.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "judge/figure.hpp"
#include "run/api.hpp"

namespace opspace::grading {

/// What a behaviour test judged of a run: one statistic of the student's run beside the same
/// statistic of the reference's run (the problem set's law in the same scenario), and the bound.
/// Shown on every simulated test, passed or failed, so that a verdict can be read off its numbers.
struct Judgement {
  std::string statistic;  ///< what is judged, e.g. "position error RMS after 1 s"
  /// Shown instead of `yours` when not empty: a value the run never took ("never" for the time
  /// of an event that did not happen, `yours` then infinite).
  std::string yours_text;
  double yours = std::numeric_limits<double>::quiet_NaN();      ///< of the student's run (SI)
  double reference = std::numeric_limits<double>::quiet_NaN();  ///< of the reference's run (SI)
  double bound = std::numeric_limits<double>::quiet_NaN();      ///< the check's bound (SI)
  bool upper = true;        ///< the bound is a maximum (at_most), else a minimum (at_least)
  double unit_scale = 1.0;  ///< SI value times this: the value shown
  std::string unit;         ///< its unit as shown
  /// How far from the reference's a run of a law that is not exactly the problem's may lie and
  /// still be the law's behaviour (law_pin.hpp, SI); NaN: a tenth of the bound. Wider only for
  /// a statistic of a chaotic run, with the spread measured on the law itself (`moved_why`).
  double moved_within = std::numeric_limits<double>::quiet_NaN();
  std::string moved_why;  ///< why moved_within is what it is, as the page says it
  /// "position error RMS after 1 s: yours 0.21 mm, the reference's 0.21 mm, bound at most 1 mm: met"
  std::string line() const;
};

/// A failed comparison of a matrix or a vector, entry by entry: for the report's table.
struct EntryTable {
  std::string what;          ///< the check's name of the value
  Eigen::MatrixXd expected;  ///< the oracle's value
  Eigen::MatrixXd computed;  ///< the student's (same shape, else no table is kept)
  double tol = 0.0;          ///< an entry is wrong beyond tol * max(1, max |expected|)
};

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
  /// Judges a measured statistic against its bound (at_most() or at_least(), by j.upper) and
  /// keeps its line (Judgement::line) for the report, whatever the verdict.
  bool judge(const Judgement& j, const std::string& meaning);
  /// Keeps a line about what was judged that is not a finding (it never changes the credit).
  void judged_note(const std::string& line) { judged_.push_back(line); }
  /// Keeps j's line and its values in the figure that draws it, without judging it: a test
  /// whose points the law withheld still shows the numbers.
  void show(const Judgement& j);
  /// Caps the test's credit at `fraction` (partial credit for a measured quantity).
  void credit_at_most(double fraction, const std::string& message);
  /// The findings say what went wrong in its place (the run stopped early, or where the law
  /// differs): the report shows no fixed hint, which could blame a part the student got right.
  void replace_hint() { hint_replaced_ = true; }
  bool hint_replaced() const { return hint_replaced_; }
  /// Keeps a run's figure for the report. Never changes the credit.
  void figure(RunFigure figure) { figures_.push_back(std::move(figure)); }

  double fraction() const { return fraction_; }  ///< share of the points earned, 0 to 1
  const std::vector<std::string>& findings() const { return findings_; }  ///< what failed, in order
  const std::vector<RunFigure>& figures() const { return figures_; }  ///< the runs the test judged
  const std::vector<std::string>& judged() const { return judged_; }  ///< what was judged, in order
  /// The statistics judged or shown (judge(), show()), in order: their values, for the suite's own tests.
  const std::vector<Judgement>& judgements() const { return judgements_; }
  /// The first failed near() of a matrix or vector of matching shape, entry by entry (empty
  /// `what` if none).
  const EntryTable& table() const { return table_; }

 private:
  void fail(const std::string& message);
  double fraction_ = 1.0;
  std::vector<std::string> findings_;
  std::vector<RunFigure> figures_;
  std::vector<std::string> judged_;
  std::vector<Judgement> judgements_;
  bool hint_replaced_ = false;
  EntryTable table_;
};

/// One graded test of a problem.
struct GradedTest {
  /// Its identity ("1b.ii.sim.part1"), declared once in problems/<key>/tests.hpp: what the known
  /// mistakes (Mistake::caught_by), the library's answers (Oracle::tests) and the handout's
  /// recorded suite name it by. Unique in the suite, no spaces; the report shows the title instead.
  std::string id;
  /// What a passing implementation does, as a sentence: what the report, results.json (the
  /// test's name on Gradescope), the class page and the replay's --test show.
  std::string title;
  double points = 0.0;  ///< what a passing implementation earns
  std::string hint;     ///< how to think about a failure
  std::function<void(const Hw2Api&, Check&)> body;  ///< runs the checks on the functions of the api
  /// A simulated test: the program and arguments that run its scenario ("hw2-p1 3"), to which
  /// the report adds --test and --seed. Empty for a test of formulas.
  std::string replay = {};
};

/// What one graded test earned.
struct TestResult {
  const GradedTest* test = nullptr;  ///< the test, owned by its Problem
  double score = 0.0;                ///< points earned: Check::fraction() times the test's points
  std::vector<std::string> findings;  ///< failed checks, or what the student code threw
  /// The student's code crashed, timed out, exited or sent garbage during this test: the
  /// findings say what happened, and no formula hint applies.
  bool interrupted = false;
  /// The grader's own call failed during this test (fault.hpp): not the student's doing.
  bool grader_fault = false;
  /// A known mistake was named for this test: the likely-mistake line replaces the hint.
  bool diagnosed = false;
  /// The findings say what went wrong in place of the hint (Check::replace_hint).
  bool hint_replaced = false;
  std::string printed;  ///< what the student's code printed during the test (sanitized, cut)
  std::vector<RunFigure> figures;  ///< the runs a simulated test judged (Check::figure)
  std::vector<std::string> judged;  ///< what a simulated test judged, yours and the reference's (Check::judge)
  std::vector<Judgement> judgements;  ///< the same statistics as values (Check::judgements)
  EntryTable table;                ///< the first wrong matrix or vector, entry by entry
  std::string mistake;             ///< the known mistake named for this test (catalogue), if any
  /// Every answer the test saw from the code was zero, as the untouched stub's are: the report,
  /// results.json and the page say so in one line (`findings`' last), without the judged values,
  /// the plots or the hint, which would only describe the stub.
  bool not_written = false;
};

/// Whether the report shows the test's fixed hint: a failed test whose findings do not already
/// say what went wrong (a crash, a named mistake, their own finding, not written yet).
inline bool shows_hint(const TestResult& r) {
  return r.score < r.test->points && !r.interrupted && !r.diagnosed && !r.hint_replaced && !r.not_written;
}

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
