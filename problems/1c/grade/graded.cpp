// Graded tests of problem 1c: the law at random states of the PUMA (the problem set's equation
// written out here), and the closed loop on the Bullet simulation, whose every tick is compared
// with that law at the same State (law_pin.hpp).
#include <problems/1c/run/scenario.hpp>
#include <opspace/model/urdf.hpp>

#include "pinned_run.hpp"
#include "answers.hpp"
#include "oracles.hpp"
#include "run_figure.hpp"
#include "graded_suite.hpp"
#include "support/random.hpp"

namespace opspace::grading {

namespace {

namespace p1b = opspace::scenarios::p1b;
namespace p1c = opspace::scenarios::p1c;
using hw2::p1c::Vector6d;

// A few products of small matrices: round-off ~1e-13 relative; 1e-6 accepts any arrangement and
// rejects every wrong term, which changes tau at order 1 (as problem 1b's law tests).
constexpr double kLawTol = 1e-6;
constexpr int kStates = 8;

const Model& puma() {
  static const Model model = load_urdf(robot_path(p1b::kRobotFile));
  return model;
}

// The problem set's law: Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p), no joint damping.
Vector6d expected_torque(const hw2::p1c::State& s, const hw2::p1c::Goal& goal) {
  return s.Jv.transpose() * (s.Lambda_v * (-goal.kpx * (s.x - goal.x_d) - goal.kvx * s.dx) + s.p);
}

// Random states around the scenario's start (within 0.5 rad, where Jv is well conditioned), random
// goals and gains, so that no hard-coded number can pass.
void law(const Hw2Api& api, Check& check) {
  testing::Random rng(seed_for(301));
  p1b::Observer observer(puma());
  for (int k = 0; k < kStates; ++k) {
    const Vector6d q = p1b::initial_q() + rng.vector(6, -0.5, 0.5);
    const Vector6d dq = rng.vector(6, -1.0, 1.0);
    const hw2::p1c::State& s = observer.observe(rng.uniform(0.0, 10.0), q, dq);
    hw2::p1c::Goal goal = p1b::goal(s.t, q);
    goal.x_d = s.x + rng.vector(3, -0.05, 0.05);
    goal.kpx = rng.uniform(10, 100);
    goal.kvx = rng.uniform(5, 30);
    goal.kvj = rng.uniform(5, 30);  // given, and unused by this law: a damping term shows
    if (!check.near("Gamma at q = " + format(q), expected_torque(s, goal), api.p1c.control(s, goal), kLawTol,
                    "the tip PD without joint damping"))
      return;
  }
}

// The graded run (~10 s) with the pin of its law (pinned_run.hpp).
using Run = PinnedRun<p1c::Result>;
const Run& run(const Hw2Api& api) {
  return pinned_run<p1c::Result>(api.identity, 0, kLawTol, [&api](LawPin& pin) {
    scenarios::RunOptions options;
    options.duration = p1c::Scenario::kGradedDuration;  // as hw2-p1c --test replays it
    const auto pinned = [control = api.p1c.control, &pin](const hw2::p1c::State& s, const hw2::p1c::Goal& goal) {
      const Vector6d tau = control(s, goal);
      pin.see(s.t, expected_torque(s, goal), tau);
      return tau;
    };
    return p1c::run(pinned, options);
  });
}

const p1c::Result& reference_run() {
  static const Hw2Api oracles = oracle::reference_api();
  return run(oracles).result;
}

double tip_max(const p1c::Result& r) { return r.summary.tip_error_max; }

void holds_the_tip(const Hw2Api& api, Check& check) {
  RunFigure f;
  f.plotted = Plotted::kLargest, f.draws = "max tip error after 2 s";
  f.quantity = "tip error |x - x_d|";
  f.unit = "mm";
  f.unit_scale = 1e3;
  f.bound = p1c::kTipErrorMax;
  f.judged = "its largest value after 2 s";
  f.judged_from = p1b::kSettleTime;
  check.figure(run_figure(f, run(api).result.samples, p1b::tip_error, "1c tip error",
                          []() -> const auto& { return reference_run().samples; }));
  const Run& r = run(api);
  if (!check.that(r.result.failure.empty(), "the run stopped early: " + r.result.failure)) return;
  Judgement j;
  j.statistic = "max tip error after 2 s", j.yours = tip_max(r.result), j.bound = p1c::kTipErrorMax;
  j.unit_scale = 1e3, j.unit = "mm";
  j.reference = reference_statistic("1c max tip error after 2 s", [] { return tip_max(reference_run()); });
  // An arm without control falls decimetres from x_d; the tip PD holds it within centimetres even
  // with the null space undamped (problems/1c/run/scenario.hpp says why 15 cm).
  judge_run(check, r.pin, "your controller", "i", {{j, "The tip PD should keep the tip near x_d = (-0.15, 0.81, 0.58)"}});
}

}  // namespace

Problem problem_1c() {
  return {"1c",
          "PUMA 560: the tip PD without joint damping (simulated)",
          {
              {"i. the law is Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p)", 3,
               "Build the task force F = Lambda_v (-kpx (x - x_d) - kvx dx) + p and map it with Jv^T; no A (-kvj dq).",
               law},
              {"ii. in simulation the tip stays within 15 cm of x_d", 3,
               "If the arm falls, check the signs and p; the law test says which term differs.", holds_the_tip,
               "hw2-p1c"},
          }};
}

namespace oracle {
hw2::p1c::Vector6d law_1c(const hw2::p1c::State& s, const hw2::p1c::Goal& goal) { return expected_torque(s, goal); }
}  // namespace oracle

}  // namespace opspace::grading
