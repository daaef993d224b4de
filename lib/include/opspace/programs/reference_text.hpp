// What a problem's reference run gives hw2-reference (apps/reference.cpp): its runs with
// solutions/ at the programs' default durations, as the C++ of reference_runs.hpp (which the
// problem's program prints beside its own values) and as the docs' fragments (the tables its
// guide quotes). Each problem writes its own, problems/<key>/run/reference.cpp, with the tools
// below; hw2-reference only loops over the problems.
#pragma once

#include <iosfwd>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "opspace/programs/verdict.hpp"
#include "opspace/scenarios/common.hpp"
#include "opspace/scenarios/summary.hpp"

namespace opspace::programs {

/// One problem's reference run, written out.
struct ReferenceText {
  /// What its declarations include, from the repository's top, e.g. "problems/2/run/scenario.hpp".
  std::vector<std::string> includes;
  /// C++ declarations inside namespace reference: each run's summary, exact.
  std::string declarations;
  /// The docs' generated fragments, {name, markdown}: the guide quotes fragment `name` between
  /// "<!-- generated: name" markers (apps/reference_docs.cpp).
  std::vector<std::pair<std::string, std::string>> fragments;
};

/// `v` as an exact C++ literal (hexadecimal floating point).
std::string exact(double v);
/// Eigen::Vector3d(x, y, z) with exact literals.
std::string exact(const Eigen::Vector3d& v);

/// Writes C++ assignments "s.member = value;" of a summary's members, values exact.
class Assignments {
 public:
  explicit Assignments(std::ostream& out) : out_(out) {}
  void operator()(const char* member, double v);
  void operator()(const char* member, long v);
  void operator()(const char* member, int v);

 private:
  std::ostream& out_;
};

/// `inline Type signature { Type s; <members of each case, under its condition>; return s; }`:
/// a function of reference_runs.hpp that returns the reference's Summary, by case (e.g. the part
/// of problem 1b: condition "part == ..."; an empty condition for a single run). `members(set,
/// summary)` calls set("member", summary.member) for each member.
template <class Summary, class Members>
void summary_function(std::ostream& out, const std::string& signature, const std::string& type,
                      const std::vector<std::pair<std::string, Summary>>& cases, Members members) {
  Assignments set(out);
  out << "inline " << type << " " << signature << " {\n  " << type << " s;\n";
  for (const auto& [condition, summary] : cases) {
    if (!condition.empty()) out << "  if (" << condition << ") {\n";
    members(set, summary);
    if (!condition.empty()) out << "  }\n";
  }
  out << "  return s;\n}\n\n";
}

/// A problem's reference run: run(options) over `duration` simulated seconds with solutions/'
/// functions. Throws std::runtime_error naming problem `key` if it stopped early.
template <class Run>
auto reference_result(const std::string& key, double duration, Run run) {
  opspace::scenarios::RunOptions options;
  options.duration = duration;
  auto result = run(options);
  if (!result.failure.empty())
    throw std::runtime_error("problem " + key + "'s reference run stopped early: " + result.failure);
  return result;
}

/// The declarations of a problem of one reference run: kP<KEY>Duration = `duration`, and
/// `type p<key>()`, its Summary `s` (summary_function).
template <class Summary, class Members>
void one_run_declarations(std::ostream& out, const std::string& key, const std::string& upper_key, double duration,
                          const std::string& type, const Summary& s, Members members) {
  out << "/// Simulated seconds of problem " << key << "'s reference run.\n"
      << "inline constexpr double kP" << upper_key << "Duration = " << duration << ";\n\n"
      << "/// solutions/' run of problem " << key << ".\n";
  summary_function<Summary>(out, "p" + key + "()", type, {{"", s}}, members);
}

/// set("member", s.member) for the members every Summary shares (scenarios::RunTotals), in the
/// order the problems' members() end with.
inline void run_totals(Assignments& set, const opspace::scenarios::RunTotals& s) {
  set("peak_torque", s.peak_torque);
  set("peak_torque_joint", s.peak_torque_joint);
  set("clamped_steps", s.clamped_steps);
  set("time_reached", s.time_reached);
}

// The docs' fragments, worded as the guides.
/// `v` with `decimals` digits after the point.
std::string fixed(double v, int decimals);
/// A value that round-off changes by percents or more (a contact solver's step-to-step sharing of
/// a push, a chaotic run): "~" tells the reader, and the docs check compares it within a factor
/// of 2 (apps/reference_docs.cpp).
std::string approx(double value, const Unit& unit);
/// How a fragment writes a number: show() or approx().
using Show = std::string (*)(double, const Unit&);
/// "max 1.23 mm, RMS 0.456 mm".
std::string max_rms(double max, double rms, const Unit& unit, Show number = &show);
/// "12.3 N m (joint 2), none clamped" or "..., 5 joint-steps clamped".
std::string torque(double peak, int joint, long clamped, Show number = &show);

}  // namespace opspace::programs
