/// @file law_pin.hpp
/// A closed-loop run measures what a law does, not which law it is: a wrong law can be made to
/// behave as a test asks (PART3's law aimed 5 cm off x_d drifts "like PART2"). So every
/// simulated test also pins the law: at every tick of the student's run, the torque the
/// student's code returned is compared with the problem set's law, the oracle of the problem's
/// law test, at the same State and Goal. A behaviour earns points only for the problem's law.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstdio>
#include <string>

#include "grading.hpp"

namespace opspace::grading {

/// The first tick of a run at which the torque was not the law's.
class LawPin {
 public:
  /// `tol` as in Check::near: |computed - expected| <= tol * max(1, |expected|), entry-wise.
  explicit LawPin(double tol) : tol_(tol) {}

  /// One tick at time t: the law's torque and the one the student's code returned.
  void see(double t, const Eigen::Ref<const Eigen::VectorXd>& expected, const Eigen::Ref<const Eigen::VectorXd>& computed) {
    ++ticks_;
    if (differs_) return;
    const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
    const bool same = computed.size() == expected.size() && computed.allFinite() &&
                      (computed - expected).cwiseAbs().maxCoeff() <= tol_ * scale;
    if (same) return;
    differs_ = true;
    t_ = t;
    expected_ = expected;
    computed_ = computed;
  }

  /// Passes if every tick applied the law; otherwise records the first tick that did not.
  /// `whose` names the law ("your PART2 controller"), `law` the equation.
  bool check(Check& check, const std::string& whose, const std::string& law) const {
    if (!check.that(ticks_ > 0, whose + " was never called in the run")) return false;
    if (!differs_) return true;
    char when[48];
    std::snprintf(when, sizeof when, "%.3f s", t_);
    return check.near(whose + "'s torque at t = " + when + " of the run", expected_, computed_, tol_,
                      "Every tick of the run must apply the problem set's law " + law +
                          ": a behaviour earns points only for that law, so this measured test earns none (the "
                          "law test says which term differs)");
  }

 private:
  double tol_;
  long ticks_ = 0;
  bool differs_ = false;
  double t_ = 0.0;
  Eigen::VectorXd expected_, computed_;
};

}  // namespace opspace::grading
