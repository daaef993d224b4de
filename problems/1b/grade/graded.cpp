// Graded tests of problem 1b. Two kinds:
// - the law: at random states of the PUMA, the student's torque equals the problem set's
//   equation written out here from the library's quantities (State from the Observer);
// - the behaviour: the closed loop on the Bullet simulation, with bounds whose reasons are
//   given beside them, measured only on the problem set's law: every tick of the run is
//   compared with the law's oracle at the same State (law_pin.hpp).
#include "opspace/algorithms/linalg.hpp"
#include <problems/1b/run/scenario.hpp>
#include "opspace/model/urdf.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "answers.hpp"
#include "judge/oracles.hpp"
#include "run_figure.hpp"
#include "judge/graded_suite.hpp"
#include <problems/1b/tests.hpp>
#include "grader/suite/random.hpp"
#include "simulated_runs.hpp"

namespace opspace::grading {

namespace p1b_graded {  // named: problems share a unity unit (problems/CMakeLists.txt)
namespace {

namespace p1b = opspace::scenarios::p1b;
using hw2::p1b::Part;
using hw2::p1b::Vector6d;
using hw2::p1b::Matrix6d;

// The law is a few products of 6x6 matrices: round-off ~1e-13 relative. 1e-6 accepts any
// correct arrangement (and a pseudo-inverse by SVD or by J^T (J J^T)^-1 at these well
// conditioned states) and rejects every wrong term, which changes tau at order 1.
constexpr double kLawTol = 1e-6;
// How far a statistic of PART2's chaotic run may lie from the reference's and still be PART2's
// behaviour (part2_drifts_more_than_part3 says how they were measured).
constexpr double kPart2Q2Moved = 0.25;    // rad
constexpr double kRatioMovedShare = 0.5;  // of the reference's ratio
constexpr int kStates = 8;

const Model& puma() {
  static const Model model = load_urdf(robot_path(p1b::kRobotFile));
  return model;
}

std::string mm(double metres) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f mm", 1e3 * metres);
  return buffer;
}

// Tip PD with gravity at the tip: Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p)
Vector6d tip_term(const hw2::p1b::State& s, const hw2::p1b::Goal& goal) {
  return s.Jv.transpose() * (s.Lambda_v * (-goal.kpx * (s.x - goal.x_d) - goal.kvx * s.dx) + s.p);
}

// Joint task with gravity: A (-kpj (q - q_d) - kvj dq) + g
Vector6d joint_term(const hw2::p1b::State& s, const hw2::p1b::Goal& goal) {
  return s.A * (-goal.kpj * (s.q - goal.q_d) - goal.kvj * s.dq) + s.g;
}

// The problem set's law for each part, the oracle of the law tests.
Vector6d expected_torque(Part part, const hw2::p1b::State& s, const hw2::p1b::Goal& goal) {
  const Matrix6d I = Matrix6d::Identity();
  switch (part) {
    case Part::kTipPd: return tip_term(s, goal) + s.A * (-goal.kvj * s.dq);
    case Part::kTipPdWithoutJointDamping: return tip_term(s, goal);
    case Part::kPseudoInverseNullspace: {
      const Eigen::MatrixXd Jv_pinv = opspace::pseudo_inverse(s.Jv);
      return tip_term(s, goal) + (I - s.Jv.transpose() * Jv_pinv.transpose()) * joint_term(s, goal);
    }
    case Part::kDynamicallyConsistentNullspace:
      return tip_term(s, goal) + (I - s.Jv.transpose() * s.Jbar_v.transpose()) * joint_term(s, goal);
  }
  return Vector6d::Zero();
}

// Random states around the scenario's start (law_at_random_states: within 0.5 rad, where Jv is
// well conditioned), random goals and gains, so that no single hard-coded number can pass.
void law(Part part, unsigned seed, const std::string& meaning, const Hw2Api& api, Check& check) {
  p1b::Observer observer(puma());
  law_at_random_states(seed, kStates, observer, p1b::initial_q(), 10.0,
                       [&](testing::Random& rng, const hw2::p1b::State& s) {
                         hw2::p1b::Goal goal = p1b::goal(s.t, s.q);
                         goal.x_d = s.x + rng.vector(3, -0.05, 0.05);
                         goal.q_d = s.q + rng.vector(6, -0.3, 0.3);
                         goal.kpx = rng.uniform(10, 100);
                         goal.kvx = rng.uniform(5, 30);
                         goal.kpj = rng.uniform(10, 100);
                         goal.kvj = rng.uniform(5, 30);
                         const Vector6d expected = expected_torque(part, s, goal);
                         return check.near("Gamma at q = " + format(s.q), expected, api.p1b.control(part, s, goal),
                                           kLawTol, meaning);
                       });
}

// The closed-loop run of each part (~1 s), with the pin of its law: the ticks, if any, at which
// the torque was not expected_torque() at that tick's State and Goal (simulated_runs.hpp). Where
// the law acts: the tip force F = Jbar_v^T tau per direction, and N^T tau = (I - Jv^T Jbar_v^T) tau.
const auto kRuns = simulated_runs<p1b::Result>(kLawTol, [](const Hw2Api& api, int variant, LawPin& pin) {
  scenarios::RunOptions options;
  options.duration = scenarios::p1b::Scenario::kGradedDuration;  // as hw2-p1 --test replays it
  pin.name_parts(point_task_parts(6));
  return p1b::run(static_cast<Part>(variant),
                  pinned_control<hw2::p1b::State>(pin, api.p1b.control, &expected_torque,
                                                  &point_task_split<hw2::p1b::State>),
                  options);
});
using Run = decltype(kRuns)::Run;
const Run& run(const Hw2Api& api, Part part) { return kRuns.run(api, static_cast<int>(part)); }
ListedRun listed_run(Part part) { return kRuns.listed(static_cast<int>(part)); }
const p1b::Result& reference_run(Part part) { return kRuns.reference(static_cast<int>(part)); }

// The series the checks read (problems/1b/run/scenario.hpp, which the programs' --test replay shares).
using p1b::q2_error;
using p1b::tip_error;

const char* part_name(Part part) {
  return part == Part::kTipPd ? "PART1" : part == Part::kPseudoInverseNullspace ? "PART2" : "PART3";
}

// The figure of the tip error of `part` in the student's run `mine`; bound NaN: none drawn.
// `plotted` says how the plot gives the statistic `draws` (its Judgement's) judges.
RunFigure tip_figure(Part part, const p1b::Result& mine, double bound, const std::string& judged,
                     Plotted plotted, const std::string& draws) {
  RunFigure f;
  f.plotted = plotted, f.draws = draws;
  f.quantity = std::string(part_name(part)) + " tip error |x - x_d|";
  f.unit = "mm";
  f.unit_scale = 1e3;
  f.bound = bound;
  f.judged = judged;
  f.judged_from = p1b::kSettleTime;
  return run_figure(f, mine.samples, tip_error, std::string("1b ") + part_name(part) + " tip error",
                    [part]() -> const auto& { return reference_run(part).samples; });
}

RunFigure q2_figure(Part part, const p1b::Result& mine, double bound) {
  RunFigure f;
  f.plotted = Plotted::kLargest, f.draws = std::string(part_name(part)) + " max q2 tracking error after 2 s";
  f.quantity = std::string(part_name(part)) + " joint 2 tracking error |q2 - q2_d|";
  f.unit = "rad";
  f.bound = bound;
  f.judged = "its largest value after 2 s";
  f.judged_from = p1b::kSettleTime;
  return run_figure(f, mine.samples, q2_error, std::string("1b ") + part_name(part) + " q2 error",
                    [part]() -> const auto& { return reference_run(part).samples; });
}

// PART2's tip error RMS over PART3's, in the student's runs or the reference's.
double drift_ratio(const p1b::Result& part2, const p1b::Result& part3) {
  return part2.summary.tip_error_rms / std::max(part3.summary.tip_error_rms, 1e-9);
}
const std::string kDriftRatio = "PART2's tip error RMS after 2 s over PART3's";

// The ratio drift_ratio() judges, as it grows over the run: PART2's running tip error RMS over
// PART3's from 2 s on (the tip errors before). Its last point is drift_ratio().
Series ratio_series(const p1b::Result& part2, const p1b::Result& part3) {
  RunFigure rms;
  rms.plotted = Plotted::kRunningRms, rms.judged_from = p1b::kSettleTime;
  const Series a = plotted_series(part2.samples, tip_error, rms.plotted, rms.judged_from);
  Series out = plotted_series(part3.samples, tip_error, rms.plotted, rms.judged_from);
  for (std::size_t k = 0; k < out.v.size(); ++k)
    out.v[k] = k < a.v.size() ? a.v[k] / std::max(out.v[k], 1e-9) : std::numeric_limits<double>::quiet_NaN();
  return out;
}

RunFigure ratio_figure(const p1b::Result& part2, const p1b::Result& part3) {
  RunFigure f;
  f.quantity = "PART2's tip error RMS over PART3's";
  f.bound = p1b::kPart2OverPart3TipErrorRmsMin, f.upper = false;
  f.judged = "its value at the end of the run (each RMS taken from 2 s on)";
  f.judged_from = p1b::kSettleTime, f.plotted = Plotted::kFinal, f.draws = kDriftRatio;
  f.student = decimate(ratio_series(part2, part3), f.judged_from);
  f.reference_key = "1b PART2 over PART3 tip error RMS";
  f.make_reference = [from = f.judged_from] {
    return decimate(ratio_series(reference_run(Part::kPseudoInverseNullspace),
                                 reference_run(Part::kDynamicallyConsistentNullspace)),
                    from);
  };
  return f;
}

// The law of `part` as its pin names it: who, the law test, the equation is the law test's.
std::string whose(Part part) { return std::string("your ") + part_name(part) + " controller"; }
const char* law_test(Part part) {
  return part == Part::kTipPd ? "ii" : part == Part::kPseudoInverseNullspace ? "iii" : "iv";
}

// The statistic `statistic` of a run of `part` (`of` reads it from the run's Summary) in the
// student's run and the reference's, with the check's bound: what a behaviour test judges.
template <class Of>
Judgement judgement(const std::string& statistic, const Hw2Api& api, Part part, Of of, double bound, double scale,
                    const std::string& unit) {
  return kRuns.judgement("1b ", statistic, api, static_cast<int>(part), of, bound, scale, unit);
}

// The run of `part` went to its end.
bool ran_to_the_end(const Run& r, Check& check) {
  return opspace::grading::ran_to_the_end(check, r.result.failure);
}

double tip_rms(const p1b::Result& r) { return r.summary.tip_error_rms; }
double tip_max(const p1b::Result& r) { return r.summary.tip_error_max; }
double q2_max(const p1b::Result& r) { return r.summary.q2_error_max; }

void part1_holds_the_tip(const Hw2Api& api, Check& check) {
  check.figure(tip_figure(Part::kTipPd, run(api, Part::kTipPd).result, p1b::kPart1TipErrorRmsMax,
                          "its RMS after 2 s, drawn from 2 s on as the running RMS", Plotted::kRunningRms,
                          "PART1 tip error RMS after 2 s"));
  const Run& r = run(api, Part::kTipPd);
  if (!ran_to_the_end(r, check)) return;
  // The tip starts 2.3 mm from x_d. A tip PD with p holds it to the mm scale; without p
  // (gravity at the tip) it would sag by about |p| / (kpx Lambda) ~ centimetres. 5 mm RMS.
  judge_run(check, r.pin, whose(Part::kTipPd), law_test(Part::kTipPd),
            {{judgement("PART1 tip error RMS after 2 s", api, Part::kTipPd, &tip_rms, p1b::kPart1TipErrorRmsMax, 1e3, "mm"),
              "The tip should converge to x_d = (-0.15, 0.81, 0.58) and stay there"}});
}

void part3_holds_the_tip_while_q2_moves(const Hw2Api& api, Check& check) {
  const Part part3 = Part::kDynamicallyConsistentNullspace;
  check.figure(tip_figure(part3, run(api, part3).result, p1b::kPart3TipErrorMax, "its largest value after 2 s",
                          Plotted::kLargest, "PART3 max tip error after 2 s"));
  check.figure(q2_figure(part3, run(api, part3).result, p1b::kPart3Q2ErrorMax));
  const Run& r = run(api, part3);
  if (!ran_to_the_end(r, check)) return;
  judge_run(check, r.pin, whose(part3), law_test(part3),
            {// Dynamically consistent: null-space torques cause no tip acceleration, so the tip
             // error stays at the PART1 scale. Bound from the issue: 5 mm after 2 s.
             {judgement("PART3 max tip error after 2 s", api, part3, &tip_max, p1b::kPart3TipErrorMax, 1e3, "mm"),
              "With the projector I - Jv^T Jbar_v^T the joint task cannot move the tip"},
             // A joint PD (kpj = 50, kvj = 20) following a sine of amplitude pi/8 at
             // w = 2 pi / 10 lags with error amplitude
             // (pi/8) |(-w^2 + j kvj w) / (kpj - w^2 + j kvj w)| = 0.096 rad (closed form of the
             // second-order response). 0.15 rad leaves room for the coupling.
             {judgement("PART3 max q2 tracking error after 2 s", api, part3, &q2_max, p1b::kPart3Q2ErrorMax, 1.0, "rad"),
              "Joint 2 should follow q_d[1] = -pi/8 + pi/8 sin(2 pi t / 10)"}});
}


void part2_drifts_more_than_part3(const Hw2Api& api, Check& check) {
  // Both runs must apply their parts' laws: a drift staged by another law (PART3's aimed off
  // x_d, say) is not the pseudo-inverse projector's lesson.
  const Part part2 = Part::kPseudoInverseNullspace, part3 = Part::kDynamicallyConsistentNullspace;
  // The ratio has no bound of its own on either series: PART2's drift is drawn without a line.
  check.figure(ratio_figure(run(api, part2).result, run(api, part3).result));
  check.figure(tip_figure(part2, run(api, part2).result, std::numeric_limits<double>::quiet_NaN(),
                          "its RMS after 2 s, drawn from 2 s on as the running RMS: at least 10 times PART3's",
                          Plotted::kRunningRms, ""));
  check.figure(q2_figure(part2, run(api, part2).result, p1b::kPart2Q2ErrorMax));
  check.figure(tip_figure(part3, run(api, part3).result, std::numeric_limits<double>::quiet_NaN(),
                          "its RMS after 2 s, drawn from 2 s on as the running RMS: at most a tenth of PART2's",
                          Plotted::kRunningRms, ""));
  if (!ran_to_the_end(run(api, part2), check) || !ran_to_the_end(run(api, part3), check)) return;
  const p1b::Result& r2 = run(api, part2).result;
  const p1b::Result& r3 = run(api, part3).result;
  // PART2 must still be the null-space law: its joint task keeps joint 2 near q_d (amplitude
  // pi/8 = 0.39 rad) even while the tip drifts, whereas an arm left without control (a
  // stub, zero torque) falls towards its hanging pose, more than 1 rad from q_d.
  // PART2's run is chaotic: the drifting arm amplifies round-off. The problem set's law with its
  // torque scaled by 1 + k 1e-12 (k = 0 ... 7, far inside the law test's 1e-6) ends with a max q2
  // error from 0.28 to 0.39 rad and a ratio from 737 to 878 (tests/mutants/test_law_gate.cpp,
  // "1b's PART2 run is chaotic ..."). So a law that is not exactly PART2's has moved these only
  // beyond twice that spread: 0.25 rad of q2 (spread 0.11), half the reference's ratio (spread
  // 141 of 878). A law staging a drift does: PART3's law aimed 5 cm off x_d ends at a ratio of
  // 149, the null-space task without g at 134.
  Judgement q2_judgement =
      judgement("PART2 max q2 tracking error after 2 s", api, part2, &q2_max, p1b::kPart2Q2ErrorMax, 1.0, "rad");
  q2_judgement.moved_within = kPart2Q2Moved;
  q2_judgement.moved_why = "twice the spread of PART2's chaotic run";
  const Judged q2{q2_judgement, "PART2 applies the joint task through its projector: joint 2 should still follow q_d"};
  // The lesson of problem 1b. With J+ the null-space torque leaves Jv^T (Jbar_v - Jv+)^T g
  // (plus the projected joint task) acting on the tip, tens of newtons at these poses, while
  // PART3 leaves none: the PART2 tip error must be at least ten times PART3's.
  Judgement ratio;
  ratio.statistic = kDriftRatio;
  ratio.yours = drift_ratio(r2, r3), ratio.bound = p1b::kPart2OverPart3TipErrorRmsMin, ratio.upper = false;
  ratio.reference = reference_statistic("1b tip error RMS of PART2 over PART3's", [] {
    return drift_ratio(reference_run(Part::kPseudoInverseNullspace), reference_run(Part::kDynamicallyConsistentNullspace));
  });
  ratio.moved_within = kRatioMovedShare * ratio.reference;  // PART2's chaos, as for q2 above
  ratio.moved_why = "half the reference's ratio (PART2's run is chaotic)";
  const Judged drift{ratio, "yours: " + mm(r2.summary.tip_error_rms) + " over " + mm(r3.summary.tip_error_rms) +
                                ". The pseudo-inverse projector is not dynamically consistent: its null-space torques "
                                "accelerate the tip"};
  // Each run is judged on its own part's law; the ratio reads both runs.
  if (!run(api, part3).pin.admits(check, whose(part3), law_test(part3), {ratio})) {
    check.show(q2.judgement);
    check.show(ratio);
    return;
  }
  judge_run(check, run(api, part2).pin, whose(part2), law_test(part2), {q2, drift});
}

}  // namespace
}  // namespace p1b_graded

Problem problem_1b() {
  using namespace p1b_graded;
  namespace id = test_id::p1b;
  return {"1b",
          "PUMA 560: tip control and null-space motion (simulated)",
          {
              {id::kLawPart1, "ii. PART1 applies Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p) + A (-kvj dq)", 3,
               "Build the task force F = Lambda_v (...) + p, map it with Jv^T, add the joint damping A (-kvj dq).",
               [](const Hw2Api& api, Check& check) {
                 law(Part::kTipPd, 201, "PART1: tip PD, gravity at the tip, joint damping", api, check);
               }},
              {id::kLawWithoutDamping,
               "ii. without joint damping the law is Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p)", 1,
               "PART1 without the A (-kvj dq) term.",
               [](const Hw2Api& api, Check& check) {
                 law(Part::kTipPdWithoutJointDamping, 202, "question ii: no joint damping", api, check);
               }},
              {id::kLawPart2, "iii. PART2 projects the joint task with I - Jv^T Jv+^T", 3,
               "Jv+ = Jv^T (Jv Jv^T)^-1 (6x3). The joint task is A (-kpj (q - q_d) - kvj dq) + g.",
               [](const Hw2Api& api, Check& check) {
                 law(Part::kPseudoInverseNullspace, 203, "PART2: pseudo-inverse null-space projector", api, check);
               }},
              {id::kLawPart3, "iv. PART3 projects the joint task with I - Jv^T Jbar_v^T", 3,
               "Use s.Jbar_v, the dynamically consistent inverse; the joint task includes g.",
               [](const Hw2Api& api, Check& check) {
                 law(Part::kDynamicallyConsistentNullspace, 204, "PART3: dynamically consistent projector", api,
                     check);
               }},
              {id::kSimPart1, "ii. in simulation PART1 brings the tip to x_d and holds it", 3,
               "If the tip sags, check p; if it oscillates or runs away, check the signs and Lambda_v.",
               part1_holds_the_tip, "hw2-p1 1"},
              {id::kSimPart3, "iv. in simulation PART3 holds the tip within 5 mm while q2 follows q_d", 4,
               "Only the dynamically consistent projector keeps the joint task out of the tip's way; "
               "without g in the joint task, joint 2 sags instead of following q_d.",
               part3_holds_the_tip_while_q2_moves, "hw2-p1 3"},
              {id::kSimDriftRatio, "iii. in simulation the PART2 tip drifts at least ten times more than PART3's", 3,
               "PART2 must use the pseudo-inverse projector, PART3 the dynamically consistent one: "
               "the difference is the point of the problem.",
               part2_drifts_more_than_part3, "hw2-p1 compare"},
          },
          // The runs in the order the tests first ask for them: PART1's test, PART3's, then the
          // drift test's PART2 (PART3 is made by then).
          {listed_run(Part::kTipPd), listed_run(Part::kDynamicallyConsistentNullspace),
           listed_run(Part::kPseudoInverseNullspace)}};
}

namespace oracle {
hw2::p1b::Vector6d law_1b(hw2::p1b::Part part, const hw2::p1b::State& s, const hw2::p1b::Goal& goal) {
  return p1b_graded::expected_torque(part, s, goal);
}
}  // namespace oracle

}  // namespace opspace::grading
