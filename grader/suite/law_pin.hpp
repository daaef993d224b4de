/// @file law_pin.hpp
/// A closed-loop run measures what a law does, not which law it is: a wrong law can be made to
/// behave as a test asks (PART3's law aimed 5 cm off x_d drifts "like PART2"). So every
/// simulated test also pins the law: at every tick of the student's run, the torque the
/// student's code returned is compared with the problem set's law, the oracle of the problem's
/// law test, at the same State and Goal.
///
/// The pin is a gate, not a second law test (docs/grader.md, "The law and the behaviour"). The
/// law test is strict and costs its own points for any wrong term. A behaviour test withholds
/// its points for the law only where the law is materially different for what it measures:
/// - a different law: at some tick the torque differs from the law's by more than
///   kDifferentLaw of the law's torque (a term left out, replaced or aimed elsewhere);
/// - or a slip that moved what the test judges: the judged statistic of the run is more than
///   kMovedShare of the bound away from the reference's (the law's run in the same scenario).
/// A slip of the law's own terms (E^+ at lambda_d instead of lambda) whose run judges as the
/// reference's earns the behaviour's points: the law test alone pays for it.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "grading.hpp"
#include "reference_store.hpp"  // reference_statistic(), for the Judgements it gates

namespace opspace::grading {

/// A torque that differs from the law's by more than this share of the law's own torque
/// (max |tau_i|, at least 1 N m) at some tick is a different law. Measured on the catalogue
/// (problems/*/grade/mistakes.cpp, each guide's rubric), the largest share over each mistake's
/// run: a term left out, replaced or aimed elsewhere differs by 2.9 % (problem 2's feed-forward
/// left out, beside the iiwa's gravity torque) to 510 % (1b's PART3 projector without I -); a
/// term of the law evaluated at a nearby point (E^+ at lambda_d, where the run keeps lambda within a
/// milliradian of lambda_d) by 0.015 %. 0.5 % lies six times below the one and thirty times
/// above the other.
inline constexpr double kDifferentLaw = 5e-3;
/// A slip moved the judged statistic when it lies further than this share of the bound from
/// the reference's. Every bound leaves the reference a margin of at least a factor of two
/// (the bounds' comments), so a move of a tenth of the bound cannot carry a run across it on
/// its own: what is left is the run's own behaviour.
inline constexpr double kMovedShare = 0.1;

/// How far the torque of a run strayed from the law's: the tick of the largest difference.
class LawPin {
 public:
  /// `tol` as in Check::near: |computed - expected| <= tol * max(1, |expected|), entry-wise.
  explicit LawPin(double tol) : tol_(tol) {}

  /// One tick at time t: the law's torque and the one the student's code returned.
  void see(double t, const Eigen::Ref<const Eigen::VectorXd>& expected, const Eigen::Ref<const Eigen::VectorXd>& computed) {
    ++ticks_;
    const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
    double share = HUGE_VAL;  // a wrong size or a value that is not finite is as far as can be
    if (computed.size() == expected.size() && computed.allFinite())
      share = (computed - expected).cwiseAbs().maxCoeff() / scale;
    if (share <= tol_) return;
    differs_ = true;
    if (share > largest_share_) largest_share_ = share, largest_t_ = t, largest_ = share * scale;
  }

  /// The gate of a behaviour test judging `judged` (yours and the reference's): passes when
  /// every tick applied the law, or when the law differs only by a slip that did not move any
  /// of `judged` by more than kMovedShare of its bound (then a line says so). `whose` names
  /// the law ("your PART3 controller"), `law_test` the problem's law test ("c").
  bool admits(Check& check, const std::string& whose, const std::string& law_test,
              const std::vector<Judgement>& judged) const {
    if (!check.that(ticks_ > 0, whose + " was never called in the run")) return false;
    if (!differs_) return true;
    const std::string differs = whose + "'s torque is not the problem set's law along the run (the law test " +
                                law_test + " shows which term): it differs by up to " + torque(largest_) + ", " +
                                percent(largest_share_) + " of the law's torque, at " + at(largest_t_);
    if (!check.that(largest_share_ <= kDifferentLaw,
                    differs + ", more than " + percent(kDifferentLaw) +
                        ": a different law, which earns no points for its behaviour, whatever the run does"))
      return false;
    for (const Judgement& j : judged) {
      const bool moved = !(std::abs(j.yours - j.reference) <= kMovedShare * std::abs(j.bound));
      if (!check.that(!moved, differs + ": a slip, but it moved the judged " + j.statistic +
                                  " more than a tenth of the bound from the reference's: this test earns none"))
        return false;
    }
    check.judged_note("a slip of the law (" + percent(largest_share_) + " of its torque at most; the law test " +
                      law_test + " costs its points) that moved nothing this test judges: the run is judged as it is");
    return true;
  }

 private:
  static std::string at(double t) { return format_number("t = %.3f s", t); }
  static std::string torque(double tau) { return format_number("%.3g N m", tau); }
  static std::string percent(double share) { return format_number("%.2g %%", 100 * share); }
  static std::string format_number(const char* format, double v) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, format, v);
    return buffer;
  }

  double tol_;
  long ticks_ = 0;
  bool differs_ = false;
  double largest_share_ = 0.0, largest_t_ = 0.0, largest_ = 0.0;
};

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
