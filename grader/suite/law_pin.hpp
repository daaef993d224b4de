/// @file law_pin.hpp
/// A closed-loop run measures what a law does, not which law it is: a wrong law can be made to
/// behave as a test asks (PART3's law aimed 5 cm off x_d drifts "like PART2"). So every
/// simulated test also pins the law: at every tick of the student's run, the torque the
/// student's code returned is compared with the problem set's law, the oracle of the problem's
/// law test, at the same State and Goal.
///
/// One rule (docs/grader.md, "The law and the behaviour"): each point is paid once, by the test
/// that examines that property. The law test pays for the law's terms. A behaviour test pays for
/// its judged statistics: when the run applied the law at every tick, they are judged against
/// their bounds; when it did not, they must also lie where the law puts them, within kMovedShare
/// of each bound of the reference's (the law's run in the same scenario). So a term that moves
/// nothing a test judges costs that test nothing, whatever its size in torque, and a different
/// law that behaves otherwise loses the test on the statistic it moved, shown with both values.
/// The pin never weighs the size of the difference: the scenarios put each known different law
/// where its run shows it (problems/<key>/run/scenario.hpp). What differs is named part by part
/// where the law acts: the task force per direction, the null-space torque per joint.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "judge/grading.hpp"
#include "judge/reference_store.hpp"  // reference_statistic(), for the Judgements it gates

namespace opspace::grading {

/// A statistic moved when it lies further than this share of its bound from the reference's.
/// Every bound leaves the reference a margin of at least a factor of two (the bounds'
/// comments), so a move of a tenth of the bound cannot carry a run across it on its own: what
/// is left is the run's own behaviour.
inline constexpr double kMovedShare = 0.1;

/// How far `j`'s statistic may lie from the reference's and not have moved: kMovedShare of its
/// bound, or what the test says of a chaotic run (Judgement::moved_within).
inline double moved_within(const Judgement& j) {
  return std::isnan(j.moved_within) ? kMovedShare * std::abs(j.bound) : j.moved_within;
}
/// Why moved_within() is what it is, as the page says it.
inline std::string moved_why(const Judgement& j) {
  return std::isnan(j.moved_within) ? "a tenth of the bound" : j.moved_why;
}
/// Whether `j`'s statistic lies further than moved_within() from the reference's.
inline bool moved(const Judgement& j) { return !(std::abs(j.yours - j.reference) <= moved_within(j)); }

/// The parts of a task-space law where they act: tau = J^T (Jbar^T tau) + N^T tau for any tau
/// (J Jbar = I, N = I - Jbar J), so Jbar^T tau is the task force it applies (one part per
/// direction) and N^T tau its null-space torque (one part per joint). Stacked: [Jbar^T; N^T].
inline Eigen::MatrixXd task_split(const Eigen::Ref<const Eigen::MatrixXd>& Jbar,
                                  const Eigen::Ref<const Eigen::MatrixXd>& N) {
  Eigen::MatrixXd split(Jbar.cols() + N.cols(), Jbar.rows());
  split << Jbar.transpose(), N.transpose();
  return split;
}

/// A part of a law where it acts, as the page names it, and the unit of its values.
struct LawPart {
  std::string name;  ///< "F_x (force-controlled)", "the null-space torque at joint 2"
  std::string unit;  ///< "N", "N m"
};

/// The parts of task_split(): the task directions given, then "the null-space torque at joint
/// k" (N m) for each of `joints`.
inline std::vector<LawPart> task_parts(std::vector<LawPart> directions, int joints) {
  for (int k = 1; k <= joints; ++k) directions.push_back({"the null-space torque at joint " + std::to_string(k), "N m"});
  return directions;
}

/// How far the torque of a run strayed from the law's, and where the law acts that it did.
class LawPin {
 public:
  /// `tol` as in Check::near: |computed - expected| <= tol * max(1, |expected|), entry-wise:
  /// round-off, not a judgement of size.
  explicit LawPin(double tol) : tol_(tol) {}

  /// Names the parts a split of see() returns (task_parts()).
  void name_parts(std::vector<LawPart> names) { names_ = std::move(names); }

  /// One tick at time t: the law's torque and the one the student's code returned, and
  /// `split()`, the matrix whose rows give the law's parts of a torque (task_split()), asked
  /// for only at a tick that differs.
  template <class Split>
  void see(double t, const Eigen::Ref<const Eigen::VectorXd>& expected, const Eigen::Ref<const Eigen::VectorXd>& computed,
           Split split) {
    ++ticks_;
    const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
    const bool comparable = computed.size() == expected.size() && computed.allFinite();
    if (comparable && (computed - expected).cwiseAbs().maxCoeff() <= tol_ * scale) return;
    differs_ = true;
    if (!comparable) return;
    const Eigen::MatrixXd s = split();
    const Eigen::VectorXd law = s * expected, difference = s * computed - law;
    if (parts_.size() != static_cast<std::size_t>(law.size())) parts_.assign(static_cast<std::size_t>(law.size()), {});
    for (Eigen::Index i = 0; i < law.size(); ++i) {
      Part& p = parts_[static_cast<std::size_t>(i)];
      p.size = std::max(p.size, std::abs(law(i)));
      if (std::abs(difference(i)) > p.largest) p.largest = std::abs(difference(i)), p.t = t, p.law = law(i);
    }
  }
  /// A tick without a split: the whole torque is one part.
  void see(double t, const Eigen::Ref<const Eigen::VectorXd>& expected, const Eigen::Ref<const Eigen::VectorXd>& computed) {
    see(t, expected, computed, [n = expected.size()] { return Eigen::MatrixXd::Identity(n, n).eval(); });
  }

  bool differs() const { return differs_; }  ///< some tick was not the law's torque
  long ticks() const { return ticks_; }

  /// Where the law differs most: up to three parts, each "F_x by up to 5.1 N (t = 2.300 s; the
  /// law's 10.2 N there)", ranked by the difference against the part's own size over the run.
  std::string where() const {
    std::vector<std::pair<double, std::size_t>> ranked;
    for (std::size_t i = 0; i < parts_.size(); ++i)
      if (parts_[i].largest > 0) ranked.push_back({parts_[i].largest / std::max(parts_[i].size, kSizeFloor), i});
    if (ranked.empty()) return "a torque that is not finite or of the wrong size";
    std::sort(ranked.rbegin(), ranked.rend());
    std::string out;
    for (std::size_t k = 0; k < ranked.size() && k < 3; ++k) {
      if (k > 0 && ranked[k].first < 0.1 * ranked[0].first) break;  // a tenth of the first: follows from it
      const Part& p = parts_[ranked[k].second];
      const LawPart named = ranked[k].second < names_.size()
                                ? names_[ranked[k].second]
                                : LawPart{"the torque at joint " + std::to_string(ranked[k].second + 1), "N m"};
      out += (k == 0 ? "" : "; ") + named.name + " by up to " + number("%.3g", p.largest) + " " + named.unit + " (" +
             number("t = %.3f s", p.t) + "; the law's " + number("%.3g", p.law) + " " + named.unit + " there)";
    }
    return out;
  }

  /// The gate of a behaviour test judging `judged` (yours and the reference's): passes when
  /// every tick applied the law, or when none of `judged` moved (moved()); then a line says so.
  /// `whose` names the law ("your PART3 controller"), `law_test` the problem's law test ("c").
  bool admits(Check& check, const std::string& whose, const std::string& law_test,
              const std::vector<Judgement>& judged) const {
    if (!check.that(ticks_ > 0, whose + " was never called in the run")) return false;
    if (!differs_) return true;
    const std::string differs = whose + " is not the problem set's law along the run (the law test " + law_test +
                                " costs its points for it): it differs in " + where();
    for (const Judgement& j : judged) {
      if (moved(j)) check.replace_hint();  // the finding names what differs
      if (!check.that(!moved(j), differs + ". That moved the judged " + j.statistic + " from the reference's " +
                                     shown(j, j.reference) + " to " + shown(j, j.yours) + ", further than " + moved_why(j) +
                                     " (" + shown(j, moved_within(j)) + "): the run is not the law's, and this test earns none"))
        return false;
    }
    std::string within;  // each statistic's allowance, once
    for (const Judgement& j : judged)
      if (within.find(moved_why(j)) == std::string::npos) within += (within.empty() ? "" : "; ") + moved_why(j);
    check.judged_note("a slip: " + differs + "; it left what this test judges where the law puts it (the reference's, "
                      "within " + within + "), so the run is judged as it is");
    return true;
  }

 private:
  /// A part's size below this (N or N m) counts as this when ranking: a part the law leaves at
  /// zero (a force-controlled direction's motion term) still ranks by what it is given.
  static constexpr double kSizeFloor = 1e-2;
  struct Part {
    double largest = 0.0, t = 0.0, law = 0.0;  ///< the largest |difference|, its time, the law's value there
    double size = 0.0;                         ///< the largest |law's value| at the ticks that differ
  };
  static std::string number(const char* format, double v) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, format, v);
    return buffer;
  }
  static std::string shown(const Judgement& j, double v) {
    return std::isnan(v) ? std::string("none") : number("%.4g", v * j.unit_scale) + (j.unit.empty() ? "" : " " + j.unit);
  }

  double tol_;
  long ticks_ = 0;
  bool differs_ = false;
  std::vector<LawPart> names_;
  std::vector<Part> parts_;
};

/// Whether a run went to its end (`failure` empty); if not, the test's finding says so, before
/// and in place of any hint.
inline bool ran_to_the_end(Check& check, const std::string& failure) {
  if (failure.empty()) return true;
  check.replace_hint();
  return check.that(false, "the run stopped early: " + failure);
}

/// A statistic a behaviour test judges, with what the problem set means by its bound.
struct Judged {
  Judgement judgement;
  std::string meaning;
};

/// Judges each of `judged` on the run when `pin` admits it (LawPin::admits); otherwise keeps
/// each one's line, so that the page shows the numbers of a test whose points the law withheld.
inline void judge_run(Check& check, const LawPin& pin, const std::string& whose, const std::string& law_test,
                      const std::vector<Judged>& judged) {
  std::vector<Judgement> judgements;
  for (const Judged& j : judged) judgements.push_back(j.judgement);
  if (!pin.admits(check, whose, law_test, judgements)) {
    for (const Judgement& j : judgements) check.show(j);
    return;
  }
  for (const Judged& j : judged) check.judge(j.judgement, j.meaning);
}

}  // namespace opspace::grading
