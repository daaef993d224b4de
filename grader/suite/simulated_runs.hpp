/// @file simulated_runs.hpp
/// What every simulated problem's graded tests share, written once (problems/1b/grade/graded.cpp
/// and each problem scripts/new-problem makes):
/// - law_at_random_states(): the law test's states, q within 0.5 rad of the start (where a tip's
///   Jv is well conditioned), dq in [-1, 1) rad/s, t in [0, t_max), from the test's seed;
/// - SimulatedRuns: the problem's runs by variant (1b's part), each made once per implementation
///   with its law pinned at every tick (pinned_run.hpp), the reference's (the oracles' in the same
///   scenario), the runs listed ahead (Problem::runs) and a statistic judged on a run (Judgement);
/// - pinned_control(): a control function that feeds the pin at every tick;
/// - point_task_parts(), point_task_split(): where a point task's law acts, for the pin.
#pragma once

#include <Eigen/Core>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "law_pin.hpp"
#include "judge/oracles.hpp"
#include "pinned_run.hpp"
#include "grader/suite/random.hpp"

namespace opspace::grading {

/// judge(rng, state) at `states` random states around q0 (the scenario's start), until it returns
/// false (a check failed: the test says so once). The draws, in order: q, dq, t; the State is
/// observer.observe(t, q, dq), or observer(t, q, dq) where `observer` is a function (problems 2
/// and 3 observe lambda on the side of lambda_d(t)).
template <class Observer, class Q, class Judge>
void law_at_random_states(unsigned seed, int states, Observer& observer, const Q& q0, double t_max, Judge judge) {
  testing::Random rng(seed_for(seed));
  for (int k = 0; k < states; ++k) {
    const Q q = q0 + rng.vector(q0.size(), -0.5, 0.5);
    const Q dq = rng.vector(q0.size(), -1.0, 1.0);
    const double t = rng.uniform(0.0, t_max);
    if constexpr (std::is_invocable_v<Observer&, double, const Q&, const Q&>) {
      if (!judge(rng, observer(t, q, dq))) return;
    } else {
      if (!judge(rng, observer.observe(t, q, dq))) return;
    }
  }
}

/// `control` with `pin` fed at every tick: pin.see(t, law(args...), tau, split(state)), the
/// State being the argument of type State (the law's inputs are the control's).
template <class State, class Control, class Law, class Split>
auto pinned_control(LawPin& pin, Control control, Law law, Split split) {
  return [control = std::move(control), law, split, &pin](const auto&... args) {
    const auto tau = control(args...);
    const State& s = std::get<const State&>(std::forward_as_tuple(args...));
    pin.see(s.t, law(args...), tau, [&s, &split] { return split(s); });
    return tau;
  };
}

/// The parts of a point task's law: the tip force F = Jbar_v^T tau per direction, then the
/// null-space torque N^T tau per joint (task_parts).
inline std::vector<LawPart> point_task_parts(int joints) {
  return task_parts({{"the tip force F_x", "N"}, {"the tip force F_y", "N"}, {"the tip force F_z", "N"}}, joints);
}
/// [Jbar_v^T; N^T] with N = I - Jbar_v Jv (task_split).
template <class State>
Eigen::MatrixXd point_task_split(const State& s) {
  using JointMatrix = decltype(s.A);  // fixed-size, as the State's
  return task_split(s.Jbar_v, JointMatrix::Identity() - s.Jbar_v * s.Jv);
}

/// A problem's simulated runs, Results of its scenario: simulate(api, variant, pin) makes the run
/// of `variant` with api's functions, its control feeding `pin` (pinned_control).
template <class Result, class Simulate>
struct SimulatedRuns {
  using Run = PinnedRun<Result>;
  double law_tolerance;  ///< the law test's (LawPin)
  Simulate simulate;

  /// The run of `api`'s implementation, made on first use.
  const Run& run(const Hw2Api& api, int variant = 0) const {
    return pinned_run<Result>(api.identity, variant, law_tolerance,
                              [&](LawPin& pin) { return simulate(api, variant, pin); });
  }
  /// The reference's run of `variant`: the problem set's law (the oracles) in the same scenario.
  const Result& reference(int variant = 0) const {
    static const Hw2Api oracles = oracle::reference_api();
    return run(oracles, variant).result;
  }
  /// The run of `variant` as Problem::runs lists it: its key and a call that asks for it.
  ListedRun listed(int variant = 0) const {
    return {[variant](std::uint64_t identity) { return run_key<Result>(identity, variant); },
            [*this, variant](const Hw2Api& api) { run(api, variant); }};
  }
  /// The statistic `statistic` (`of` reads it from a Result) of the student's run and of the
  /// reference's (kept as `key` + statistic), with its bound: what a behaviour test judges.
  template <class Of>
  Judgement judgement(const std::string& key, const std::string& statistic, const Hw2Api& api, int variant, Of of,
                      double bound, double scale, const std::string& unit) const {
    Judgement j;
    j.statistic = statistic, j.yours = of(run(api, variant).result), j.bound = bound, j.unit_scale = scale,
    j.unit = unit;
    j.reference = reference_statistic(key + statistic, [this, of, variant] { return of(reference(variant)); });
    return j;
  }
};

/// SimulatedRuns<Result, Simulate>{law_tolerance, simulate}, its types deduced.
template <class Result, class Simulate>
SimulatedRuns<Result, Simulate> simulated_runs(double law_tolerance, Simulate simulate) {
  return {law_tolerance, simulate};
}

}  // namespace opspace::grading
