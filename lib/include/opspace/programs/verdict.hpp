// The end of a run that judges itself: every number beside what it should be, i.e. the bound
// the graded suite applies (the constants of the scenario headers, shared with problems/<key>/grade/graded.cpp)
// and the reference run's value (solutions/, run at build time: reference_runs.hpp).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "opspace/math/constants.hpp"

namespace opspace::programs {

/// How a quantity is shown: its SI value times `scale`, followed by `name`.
struct Unit {
  const char* name;
  double scale;
};
inline constexpr Unit kMm{"mm", 1e3};
inline constexpr Unit kRad{"rad", 1.0};
inline constexpr Unit kDegrees{"deg", 180.0 / opspace::kPi};
inline constexpr Unit kNewton{"N", 1.0};
inline constexpr Unit kNewtonMetre{"N m", 1.0};
inline constexpr Unit kSeconds{"s", 1.0};
inline constexpr Unit kSteps{"steps", 1.0};
inline constexpr Unit kJointSteps{"joint-steps", 1.0};
inline constexpr Unit kNone{"", 1.0};

/// `value` in `unit` with three significant digits (at least the units): "815 mm", "0.621 mm".
std::string show(double value, const Unit& unit);

/// The same without trailing zeros, for bounds: "0.5 deg", not "0.500 deg".
std::string show_bound(double value, const Unit& unit);

/// A table of results: one row per quantity with this run's value, the graded bound (or
/// "not graded") and the reference run's value, and "ok" or "MISSES" against the bound.
class Verdict {
 public:
  /// `reference` heads the reference column, e.g. "reference (10 s)"; `value` and `should`
  /// head the columns of this run's value and of what it should be.
  explicit Verdict(std::string reference, std::string value = "this run", std::string should = "grader's bound");

  /// A heading row, e.g. "after 2 s".
  void section(const std::string& title);
  /// A graded quantity that must stay <= bound.
  void at_most(const std::string& what, double value, double bound, double reference, const Unit& unit);
  /// A graded quantity that must stay >= bound.
  void at_least(const std::string& what, double value, double bound, double reference, const Unit& unit);
  /// A quantity the grader does not bound: this run and the reference only.
  void shown(const std::string& what, double value, double reference, const Unit& unit);
  /// A row of texts: what, this run, what it should be, the reference, and the verdict ("ok",
  /// "" when nothing is judged, anything else a miss, e.g. "MISSES"). For values with a joint
  /// number, a time, or a bound in words.
  void row(const std::string& what, std::string value, std::string should, std::string reference,
           std::string verdict = "");
  /// An explanation under the last row, indented.
  void note(const std::string& text);

  /// How many rows missed (a verdict other than "ok" and "").
  int misses() const { return misses_; }
  /// Prints the table, then (if some bound was missed) where the grader explains it.
  void print(std::ostream& out, const std::string& grade_hint) const;

 private:
  struct Row {
    std::string what, value, should, reference, verdict;
    bool heading = false, is_note = false;
  };
  std::string reference_, value_, should_;
  std::vector<Row> rows_;
  int misses_ = 0;
};

/// " (joint 3)" for the 0-based joint index 2.
std::string joint(int index);

}  // namespace opspace::programs
