// Graded tests of problem 2. Three kinds:
// - the desired acceleration (2a) and its conversion to [vdot_d; wdot_d] (2b), against the
//   problem set's closed forms, the library's E^+ and finite differences of the trajectory;
// - the law (2c): at random states of the iiwa, the student's torque equals the problem set's
//   equation written out here from the library's quantities (State from the Observer);
// - the behaviour: the closed loop on the Bullet simulation, with bounds whose reasons are
//   given beside them, measured only on the problem set's law: every tick of the run is
//   compared with the law's oracle at the same State and Goal (law_pin.hpp).
#include "opspace/math/constants.hpp"
#include "opspace/algorithms/euler_params.hpp"
#include <problems/2/run/scenario.hpp>
#include "opspace/model/urdf.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "simulated_runs.hpp"
#include "answers.hpp"
#include "judge/oracles.hpp"
#include "run_figure.hpp"
#include "judge/graded_suite.hpp"
#include <problems/2/tests.hpp>
#include <problems/2/problem_set.hpp>
#include "grader/suite/random.hpp"

namespace opspace::grading {

namespace p2_graded {  // named: problems share a unity unit (problems/CMakeLists.txt)
namespace {

namespace p2 = opspace::scenarios::p2;
using hw2::p2::Vector6d;
using hw2::p2::Vector7d;
using testing::problem_set_xddot_d;

// Closed forms evaluated in another order differ by round-off (~1e-15); a wrong coefficient
// or term changes the result at order 0.01-1. 1e-9 separates the two.
constexpr double kFormulaTol = 1e-9;
// The law is a few products of 6x6 and 7x7 matrices: round-off ~1e-13 relative. 1e-6 accepts
// any correct arrangement and rejects every wrong term, which changes tau at order 1.
constexpr double kLawTol = 1e-6;
constexpr int kSamples = 8;

const Model& iiwa() {
  static const Model model = load_urdf(robot_path(p2::kRobotFile));
  return model;
}

void desired_acceleration_is_the_second_derivative(const Hw2Api& api, Check& check) {
  testing::Random rng(seed_for(221));
  for (int k = 0; k < kSamples; ++k) {
    const double t = rng.uniform(0.0, 10.0);
    const Vector7d computed = api.p2.desired_acceleration(t);
    char when[32];
    std::snprintf(when, sizeof when, "t = %.4f s", t);
    if (!check.near(std::string("xddot_d at ") + when, problem_set_xddot_d(t), computed, kFormulaTol,
                    "the problem set's closed forms of 2(a)")) {
      return;
    }
    // Second central difference of x_d(t) with h = 1e-3: truncation h^2 |x""| / 12 ~ 1e-6
    // (every derivative of x_d is a few units), round-off 1e-16 / h^2 = 1e-10. Bound 1e-5.
    const double h = 1e-3;
    const Vector7d fd = (p2::desired(t + h).x - 2 * p2::desired(t).x + p2::desired(t - h).x) / (h * h);
    if (!check.near(std::string("xddot_d vs finite differences of x_d at ") + when, fd, computed, 1e-5,
                    "d^2/dt^2 of x_d(t) by finite differences")) {
      return;
    }
  }
}

void twist_acceleration_is_E_pinv_xddot(const Hw2Api& api, Check& check) {
  testing::Random rng(seed_for(222));
  for (int k = 0; k < kSamples; ++k) {
    const Eigen::Vector4d lambda = Eigen::Vector4d(rng.vector(4)).normalized();
    const Vector7d xddot = rng.vector(7, -2.0, 2.0);
    if (!check.near("[vdot; wdot] at lambda = " + format(lambda.transpose()),
                    representation_matrix_pinv(lambda) * xddot, api.p2.desired_twist_acceleration(lambda, xddot),
                    kFormulaTol, "E^+ = diag(I3, E_r^+), E_r^+ = 4 E_r^T for a unit lambda")) {
      return;
    }
  }
  // Along the trajectory, E_r^+(lambda_d) lambdaddot_d is the derivative of the angular
  // velocity w_d = E_r^+(lambda_d) lambdadot_d (the term E_r^+ Edot_r w vanishes): central
  // differences with h = 1e-4 are exact to ~1e-8; bound 1e-6.
  const double h = 1e-4;
  auto w_d = [](double t) {
    const p2::Reference r = p2::desired(t);
    return Eigen::Vector3d(euler_rate_matrix_pinv(r.x.tail<4>()) * r.xdot.tail<4>());
  };
  for (int k = 0; k < kSamples; ++k) {
    const double t = rng.uniform(0.0, 10.0);
    const p2::Reference r = p2::desired(t);
    const Vector6d computed = api.p2.desired_twist_acceleration(r.x.tail<4>(), r.xddot);
    if (!check.near("wdot_d along the trajectory", (w_d(t + h) - w_d(t - h)) / (2 * h), computed.tail<3>(), 1e-6,
                    "the derivative of the desired angular velocity")) {
      return;
    }
  }
}

// The problem set's law, the oracle of the law test.
Vector7d expected_torque(const hw2::p2::State& s, const hw2::p2::Goal& goal) {
  const Matrix67d E_pinv = representation_matrix_pinv(s.lambda);  // at the CURRENT lambda
  Vector6d error, twist;
  error << s.x_p - goal.x_d.head<3>(), orientation_error(s.lambda, goal.x_d.tail<4>());
  twist << s.v, s.w;
  const Vector6d F =
      s.Lambda0 * (-goal.kpx * error - goal.kvx * (twist - E_pinv * goal.xdot_d) + E_pinv * goal.xddot_d) + s.p;
  return s.J0.transpose() * F + s.N0.transpose() * (s.A * (-goal.kvj * s.dq) + s.g);
}

// Random states around the scenario's start (within 0.5 rad, where J0 is well conditioned),
// random goals (lambda_d a few tenths from lambda, so that E^+ at lambda and at lambda_d
// differ) and random gains, so that no single hard-coded number can pass.
void law(const Hw2Api& api, Check& check) {
  p2::Observer observer(iiwa());
  const auto observe = [&observer](double t, const Vector7d& q, const Vector7d& dq) -> const hw2::p2::State& {
    return observer.observe(t, q, dq, p2::desired(t).x.tail<4>());
  };
  const auto judge = [&](testing::Random& rng, const hw2::p2::State& s) {
    hw2::p2::Goal goal = p2::goal(s.t);
    const Eigen::Vector4d lambda_d = (s.lambda + rng.vector(4, -0.3, 0.3)).normalized();
    goal.x_d << s.x_p + rng.vector(3, -0.05, 0.05), lambda_d;
    // a physical xdot_d: lambdadot_d = E_r(lambda_d) w_d
    goal.xdot_d << rng.vector(3, -0.2, 0.2), euler_rate_matrix(lambda_d) * rng.vector(3, -2.0, 2.0);
    goal.xddot_d = rng.vector(7, -2.0, 2.0);
    goal.kpx = rng.uniform(10, 100);
    goal.kvx = rng.uniform(5, 30);
    goal.kvj = rng.uniform(5, 30);
    return check.near("Gamma at q = " + format(s.q.transpose()), expected_torque(s, goal),
                      api.p2.control(s, goal), kLawTol,
                      "decoupled PD + feed-forward + p, null-space damping + g");
  };
  law_at_random_states(223, kSamples, observe, p2::initial_q(), 10.0, judge);
}

// The closed-loop run with the pin of its law: the ticks, if any, at which the torque was not
// expected_torque() at that tick's State and Goal. The run's feed-forward xddot_d is the
// problem set's (the grader's closed forms), not the student's 2(a): 2(a) has its own test, so
// a wrong 2(a) costs that test alone and cannot be answered differently during a run.
// The run costs ~0.6 s (pinned_run.hpp).
const auto kRuns = simulated_runs<p2::Result>(kLawTol, [](const Hw2Api& api, int, LawPin& pin) {
  scenarios::RunOptions options;
  options.duration = scenarios::p2::Scenario::kGradedDuration;  // two periods: the drift test compares them
  // Where the law acts: the task force [F; M] = Jbar0^T tau per direction, and N0^T tau.
  pin.name_parts(task_parts({{"F_x", "N"}, {"F_y", "N"}, {"F_z", "N"}, {"M_x", "N m"}, {"M_y", "N m"}, {"M_z", "N m"}}, 7));
  const auto split = [](const hw2::p2::State& s) { return task_split(s.Jbar0, s.N0); };
  return p2::run(pinned_control<hw2::p2::State>(pin, api.p2.control, &expected_torque, split),
                 problem_set_xddot_d, options);
});
using Run = decltype(kRuns)::Run;
const Run& run(const Hw2Api& api) { return kRuns.run(api); }

// The reference's run: the problem set's law (the oracles) in the same scenario.
const p2::Result& reference_run() { return kRuns.reference(); }

// The series the checks read (problems/2/run/scenario.hpp, which the programs' --test replay shares).
using p2::lambda_dot_lambda_d;
using p2::position_error;
const auto orientation_error_angle = &p2::orientation_angle;
// How far the joint nearest a URDF limit is past it (rad; negative: within its limits).
double limit_excess(const p2::Sample& s) {
  double excess = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < 7; ++i) {
    const Body& body = iiwa().bodies[static_cast<std::size_t>(i)];
    excess = std::max(excess, std::max(body.lower - s.q(i), s.q(i) - body.upper));
  }
  return excess;
}
// The largest limit_excess() over the run `r`: what the limits test judges, read from the series
// its figure plots (the URDF's limits as this file loads them).
double largest_limit_excess(const p2::Result& r) {
  double largest = -std::numeric_limits<double>::infinity();
  for (const p2::Sample& s : r.samples) largest = std::max(largest, limit_excess(s));
  return largest;
}
// max_i |q_i(t) - q_i(t - kPeriod)| (rad) at each sample of `samples` from one period on, 0 before.
auto period_drift(const std::vector<p2::Sample>& samples) {
  return [&samples](const p2::Sample& s) {
    const auto k = static_cast<std::size_t>(&s - samples.data());
    const auto per_period = static_cast<std::size_t>(std::lround(p2::kPeriod / (samples.size() > 1 ? samples[1].t - samples[0].t : 1.0)));
    return k >= per_period && per_period > 0 ? (s.q - samples[k - per_period].q).cwiseAbs().maxCoeff() : 0.0;
  };
}

// The figure of `value` in the student's run `r` and the reference's ("2 " + key).
template <class Value>
RunFigure figure_of(RunFigure f, const p2::Result& r, Value value, const std::string& key) {
  return run_figure(f, r.samples, value, "2 " + key, []() -> const auto& { return reference_run().samples; });
}

// The statistics the behaviour tests judge, as their Judgements and figures name them.
const std::string kPositionRms = "position error RMS after 1 s";
const std::string kOrientationRms = "orientation error RMS after 1 s (angle of R R_d^T)";
const std::string kLimitExcess = "largest excursion past a URDF joint limit";
const std::string kDrift = "joint drift between t = 5 s and t = 10 s (largest over the joints)";

// The figure of `test` (its first check's quantity) in the student's run.
void figure(const std::string& test, const Hw2Api& api, Check& check) {
  const p2::Result& r = run(api).result;
  RunFigure f;
  f.judged_from = p2::kSettleTime;
  if (test == "position") {
    f.quantity = "position error |x_p - x_pd|", f.unit = "mm", f.unit_scale = 1e3;
    f.bound = p2::kPositionErrorRmsMax, f.judged = "its RMS after 1 s, drawn from 1 s on as the running RMS";
    f.plotted = Plotted::kRunningRms, f.draws = kPositionRms;
    check.figure(figure_of(f, r, position_error, "position error"));
  } else if (test == "orientation") {
    f.quantity = "orientation error (angle of R R_d^T)", f.unit = "deg", f.unit_scale = 1.0 / kDeg;
    f.bound = p2::kOrientationErrorRmsMax, f.judged = "its RMS after 1 s, drawn from 1 s on as the running RMS";
    f.plotted = Plotted::kRunningRms, f.draws = kOrientationRms;
    check.figure(figure_of(f, r, orientation_error_angle, "orientation error"));
  } else if (test == "limits") {
    f.quantity = "largest excursion past a URDF joint limit", f.unit = "deg", f.unit_scale = 1.0 / kDeg;
    f.bound = p2::kJointLimitExcessMax, f.judged = "its largest value over the run";
    f.judged_from = 0.0, f.plotted = Plotted::kLargest, f.draws = kLimitExcess;
    check.figure(figure_of(f, r, limit_excess, "joint limit excess"));
  } else if (test == "drift") {
    f.quantity = "joint drift over one period, max_i |q_i(t) - q_i(t - 5 s)|", f.unit = "deg", f.unit_scale = 1.0 / kDeg;
    f.bound = p2::kJointDriftPerPeriodMax, f.judged = "its value at the end of the run";
    f.judged_from = p2::kSettleTime + p2::kPeriod, f.plotted = Plotted::kFinal, f.draws = kDrift;
    RunFigure made = run_figure(f, r.samples, period_drift(r.samples), "2 joint drift",
                                []() -> const auto& { return reference_run().samples; });
    // period_drift indexes the samples it is given: the reference's series reads its own run.
    made.make_reference = [shape = made] {
      return decimate(reference_run().samples, period_drift(reference_run().samples), shape);
    };
    check.figure(std::move(made));
  } else {
    f.quantity = "lambda . lambda_d (lambda flips where it would cross 0)";
    f.judged = "no bound on it: the check reads the largest step of lambda";
    check.figure(figure_of(f, r, lambda_dot_lambda_d, "lambda dot lambda_d"));
  }
}

// The statistic `statistic` of a run (`of` reads it from the run's Summary) in the student's run
// `mine` and the reference's, with the check's bound: what a behaviour test judges.
template <class Of>
Judgement judgement(const std::string& statistic, const p2::Result& mine, Of of, double bound, double scale,
                    const std::string& unit) {
  Judgement j;
  j.statistic = statistic, j.yours = of(mine), j.bound = bound, j.unit_scale = scale, j.unit = unit;
  j.reference = reference_statistic("2 " + statistic, [of] { return of(reference_run()); });
  return j;
}

// Judges `judged` on the run, when it went to its end on the problem set's law or on a slip of
// it that moved nothing the test judges (law_pin.hpp).
void judge(const Hw2Api& api, Check& check, const std::vector<Judged>& judged) {
  const Run& r = run(api);
  if (!ran_to_the_end(check, r.result.failure)) return;
  judge_run(check, r.pin, "your controller", "c", judged);
}

void position_tracking(const Hw2Api& api, Check& check) {
  figure("position", api, check);
  const p2::Result& r = run(api).result;
  // Without the feed-forward acceleration the PD lags y_d (0.1 m at w = 2 pi/5) by
  // 0.1 w^2 / |kpx - w^2 + j kvx w| = 2.9 mm and z_d (0.05 m at 2w) by
  // 0.05 (2w)^2 / |kpx - 4 w^2 + 2 j kvx w| = 4.7 mm: 3.9 mm RMS (closed form of the
  // second-order error dynamics). With it, only the uncompensated Coriolis forces remain
  // (tenths of a mm on the reference). 1 mm RMS separates the two.
  judge(api, check,
        {{judgement(kPositionRms, r, [](const p2::Result& x) { return x.summary.position_error_rms; },
                    p2::kPositionErrorRmsMax, 1e3, "mm"),
          "link7's origin should follow x_d = (0, 0.5 + 0.1 cos(2 pi t/5), 0.65 - 0.05 cos(4 pi t/5))"}});
}

void orientation_tracking(const Hw2Api& api, Check& check) {
  figure("orientation", api, check);
  const p2::Result& r = run(api).result;
  // lambda_d turns about a fixed axis by 2a = (pi/2) cos(w t): angular acceleration amplitude
  // (pi/2) w^2 = 2.5 rad/s^2. Without feed-forward the PD lags it by
  // 2.5 / |kpx - w^2 + j kvx w| = 0.045 rad (0.032 rad RMS); with it the error is set by the
  // uncompensated Coriolis forces (about a milliradian). 0.01 rad (0.57 deg) RMS separates them.
  judge(api, check,
        {{judgement(kOrientationRms, r,
                    [](const p2::Result& x) { return x.summary.orientation_error_rms; }, p2::kOrientationErrorRmsMax,
                    1.0 / kDeg, "deg"),
          "link7 should turn with lambda_d(t)"}});
}

void euler_parameters_stay_continuous(const Hw2Api& api, Check& check) {
  figure("lambda", api, check);
  const p2::Result& r = run(api).result;
  judge(api, check,
        {// lambda comes from an orthonormal R, normalised: unit to rounding.
         {judgement("largest ||lambda| - 1| over the run", r,
                    [](const p2::Result& x) { return x.summary.lambda_norm_error_max; }, p2::kLambdaNormErrorMax, 1.0, ""),
          "|lambda| drifted from 1"},
         // |lambda(t + dt) - lambda(t)| = |E_r w| dt = |w| dt / 2. The iiwa's joint speed limits
         // sum to 16 rad/s, so a continuous lambda moves at most 8e-3 per 1 ms step; 0.01 allows
         // that. A jump of about 2 is lambda flipping to -lambda: the orientation went half a
         // turn away from lambda_d, where lambda . lambda_d changes sign.
         {judgement("largest change of lambda in one 1 ms step", r,
                    [](const p2::Result& x) { return x.summary.lambda_step_max; }, p2::kLambdaStepMax, 1.0, ""),
          "lambda flips sign only when link7 is half a turn away from lambda_d"}});
}

void joints_stay_near_their_limits(const Hw2Api& api, Check& check) {
  figure("limits", api, check);
  const p2::Result& r = run(api).result;
  // The problem set's law has no joint-limit task and the simulation does not enforce limits.
  // The task fixes six of the seven joints' motions and the damped self-motion follows the
  // task (next test), so a correct law drives the same joint path as the reference, whose
  // joint 1 reaches 171.9 deg at the far end of the y sweep, 1.9 deg past its 170 deg limit.
  // 5 deg allows that and flags an arm that swings away from the task's joint path.
  judge(api, check,
        {{judgement(kLimitExcess, r,
                    &largest_limit_excess, p2::kJointLimitExcessMax,
                    1.0 / kDeg, "deg"),
          "the joints should stay within their URDF limits (yours: joint " +
              std::to_string(r.summary.joint_limit_joint + 1) + " comes nearest)"}});
}

void self_motion_is_damped(const Hw2Api& api, Check& check) {
  figure("drift", api, check);
  const p2::Result& r = run(api).result;
  // The iiwa has one redundant degree of freedom. N0^T A (-kvj dq) damps its self-motion at
  // rate kvj = 20 /s (time constant 0.05 s, a hundredth of the 5 s period), so the joints
  // follow the periodic task with a period of their own, up to a slow geometric drift (the
  // damped joint path of a closed task path need not close: under a degree per period on the
  // reference). Undamped, the self-motion keeps what the Coriolis coupling pumps into it and
  // wanders by tens of degrees per period. 0.1 rad (5.7 deg) separates the two.
  judge(api, check,
        {{judgement(kDrift, r,
                    [](const p2::Result& x) { return x.summary.joint_drift_per_period; }, p2::kJointDriftPerPeriodMax,
                    1.0 / kDeg, "deg"),
          "the arm should repeat its motion every 5 s period (joint " +
              std::to_string(r.summary.joint_drift_joint + 1) + " drifts most)"}});
}

}  // namespace
}  // namespace p2_graded

Problem problem_2() {
  using namespace p2_graded;
  namespace id = test_id::p2;
  return {"2",
          "KUKA iiwa: position and Euler-parameter trajectory tracking (simulated)",
          {
              {id::kAcceleration,
               "a. xddot_d is the second time derivative of x_d(t), as in the closed forms of 2(a)", 2,
               "Differentiate twice with the chain rule: a = (pi/4) cos(2 pi t/5), so d^2/dt^2 sin(a) = "
               "cos(a) a'' - sin(a) a'^2. The x component is 0.",
               desired_acceleration_is_the_second_derivative},
              {id::kTwistAcceleration,
               "b. [vdot_d; wdot_d] = E^+(lambda) xddot_d, with E_r^+ = (E_r^T E_r)^-1 E_r^T = 4 E_r^T", 2,
               "E^+ = diag(I3, E_r^+) is 6x7; evaluate E_r at the lambda passed in. The term E_r^+ Edot_r w is "
               "zero for Euler parameters.",
               twist_acceleration_is_E_pinv_xddot},
              {id::kLaw,
               "c. the controller applies J0^T (Lambda0 (-kpx [x_p - x_pd; delta_phi] - kvx ([v; w] - E^+ xdot_d) "
               "+ [vdot_d; wdot_d]) + p) + N0^T (A (-kvj dq) + g)",
               4,
               "delta_phi = E_r^+ (lambda - lambda_d); every E^+ at the CURRENT s.lambda (not lambda_d); "
               "[vdot_d; wdot_d] from your 2(b) with goal.xddot_d; the joint damping and g go through N0^T.",
               law},
              {id::kSimPosition,
               "d. in simulation link7's origin follows the desired position within 1 mm RMS after 1 s", 3,
               "A lag of a few mm that grows with the trajectory's curvature is a missing feed-forward "
               "[vdot_d; wdot_d]; centimetres mean the joint damping is not projected with N0^T.",
               position_tracking, "hw2-p2"},
              {id::kSimOrientation,
               "d. in simulation link7's orientation follows lambda_d within 0.01 rad RMS after 1 s", 3,
               "If link7 turns away from lambda_d, check the sign of delta_phi (-kpx delta_phi must turn it "
               "back); a steady lag of a few degrees is a missing feed-forward.",
               orientation_tracking, "hw2-p2"},
              {id::kSimContinuous,
               "d. in simulation lambda stays unit and continuous: link7 never turns half a turn from lambda_d", 1,
               "The library keeps lambda on the side of lambda_d; a jump means the orientation error reached "
               "180 degrees, i.e. the orientation feedback pushes away from lambda_d (sign of delta_phi).",
               euler_parameters_stay_continuous, "hw2-p2"},
              {id::kSimJointLimits, "d. in simulation no joint goes more than 5 degrees past its URDF limit", 1,
               "A correct law follows the reference's joint path; an arm that swings far from it has an "
               "unstable task (check delta_phi's sign) or an undamped null space.",
               joints_stay_near_their_limits, "hw2-p2"},
              {id::kSimSelfMotion,
               "d. in simulation the arm repeats its motion every period: the null-space self-motion is damped", 2,
               "Without N0^T A (-kvj dq) the elbow's self-motion is free: the task is tracked, but the arm's "
               "posture wanders a little more every period (and would eventually hit a joint limit).",
               self_motion_is_damped, "hw2-p2"},
          }};
}

namespace oracle {
hw2::p2::Vector7d law_2(const hw2::p2::State& s, const hw2::p2::Goal& goal) {
  return p2_graded::expected_torque(s, goal);
}
}  // namespace oracle

}  // namespace opspace::grading
