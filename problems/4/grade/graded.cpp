// Graded tests of problem 4. Two kinds:
// - the analysis (questions i-iv): analysis.cpp;
// - question v: the law at random states against the equation written out here, and the
//   closed loop on the Bullet simulation, beside the plain operational-space controller,
//   measured only on the problem set's law: every tick of the run is compared with the law's
//   oracle at the same State and Goal (law_pin.hpp).
#include "opspace/math/constants.hpp"
#include <problems/4/run/scenario.hpp>
#include "opspace/model/urdf.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "simulated_runs.hpp"
#include "analysis.hpp"
#include "answers.hpp"
#include "judge/oracles.hpp"
#include "run_figure.hpp"
#include "judge/graded_suite.hpp"
#include <problems/4/tests.hpp>
#include "grader/suite/random.hpp"

namespace opspace::grading {

namespace p4_graded {  // named: problems share a unity unit (problems/CMakeLists.txt)
namespace {

namespace p4 = opspace::scenarios::p4;
using hw2::p4::Kinematics;
using hw2::p4::Target;
using opspace::SingularityType;

// The law is a few products of 3x3 matrices: 1e-6 relative, as in problem 1b.
constexpr double kLawTol = 1e-6;
constexpr int kSamples = 6;
// Torque limit of every joint in robots/rrr.urdf (effort = 50 N m).
constexpr double kEffortLimit = p4::kPeakTorqueMax;
// Task dynamics xdd = -kpx e - kvx de with kpx = 50, kvx = 20 have poles -10 +- sqrt(50), the
// slow one at 2.93 /s: 10 cm decay to 5 mm in ln(20) / 2.93 = 1.02 s once the direction is
// controllable. The self-motion potential (same gains) needs a few tenths of a second to
// leave the lock. 2 s leaves room for both; the run lasts p4::kDuration = 3 s.
constexpr double kReachBound = p4::kReachTimeMax;

// The law of question v, the oracle of the law test.
Eigen::Vector3d expected_torque(Target target, const hw2::p4::State& s, const hw2::p4::Goal& goal) {
  Eigen::Vector3d q_d = s.q;
  q_d(target == Target::kAlongZ0 ? 2 : 0) =
      target == Target::kAlongZ0 ? hw2::p4::kRetractedElbow : hw2::p4::kTurnedJoint1;
  const Eigen::Vector3d F = s.Lambda_v * (-goal.kpx * (s.x - goal.x_d) - goal.kvx * s.dx) + s.p;
  return s.Jv.transpose() * F + s.N.transpose() * (s.A * (-goal.kpj * (s.q - q_d) - goal.kvj * s.dq) + s.g);
}

void law(const Hw2Api& api, Check& check) {
  testing::Random rng(seed_for(402));
  p4::Observer observer(rrr());
  for (Target target : {Target::kAlongZ0, Target::kAlongY0}) {
    for (int k = 0; k < kSamples; ++k) {
      // Within 0.3 rad of each start, close to the locks where the robust Lambda_v matters;
      // random goals and gains, so that no hard-coded number can pass.
      const Eigen::Vector3d q = p4::initial_q(target) + Eigen::Vector3d(rng.vector(3, -0.3, 0.3));
      const Eigen::Vector3d dq = rng.vector(3, -1.0, 1.0);
      const hw2::p4::State& s = observer.observe(0.0, q, dq);
      hw2::p4::Goal goal = p4::goal(target);
      goal.x_d = s.x + Eigen::Vector3d(rng.vector(3, -0.1, 0.1));
      goal.kpx = rng.uniform(10, 100);
      goal.kvx = rng.uniform(5, 30);
      goal.kpj = rng.uniform(10, 100);
      goal.kvj = rng.uniform(5, 30);
      if (!check.near("Gamma " + p4::describe(target) + " at " + deg(q), expected_torque(target, s, goal),
                      api.p4.control(target, s, goal), kLawTol,
                      "Gamma = Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p) + N^T (A (-kpj (q - q_d) - kvj dq) + g)"))
        return;
    }
  }
}

// A closed-loop run toward one target (~0.1 s), with the pin of its law: the ticks, if any, at
// which the torque was not expected_torque() at that tick's State and Goal (pinned_run.hpp).
const auto kRuns = simulated_runs<p4::Result>(kLawTol, [](const Hw2Api& api, int variant, LawPin& pin) {
  scenarios::RunOptions options;
  options.duration = scenarios::p4::Scenario::kGradedDuration;  // as hw2-p4 --test replays it
  // Where the law acts: the tip force Jbar_v^T tau per direction, and N^T tau (the State's robust N).
  pin.name_parts(point_task_parts(3));
  const auto split = [](const hw2::p4::State& s) { return task_split(s.Jbar_v, s.N); };
  return p4::run(static_cast<Target>(variant),
                 pinned_control<hw2::p4::State>(pin, api.p4.control, &expected_torque, split), options);
});
using Run = decltype(kRuns)::Run;
const Run& run(const Hw2Api& api, Target target) { return kRuns.run(api, static_cast<int>(target)); }

const p4::Result& run_plain(Target target) {
  static std::map<int, p4::Result> cache;
  auto it = cache.find(static_cast<int>(target));
  if (it == cache.end()) {
    scenarios::RunOptions options;
    options.duration = p4::kDuration;
    it = cache.emplace(static_cast<int>(target), p4::run_plain(target, options)).first;
  }
  return it->second;
}

std::string seconds(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f s", t);
  return t < 0 ? "never" : buffer;
}

std::string millimetres(double metres) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f mm", 1e3 * metres);
  return buffer;
}

// The reference's run toward `target`: the problem set's law (the oracles) in the same scenario.
const p4::Result& reference_run(Target target) { return kRuns.reference(static_cast<int>(target)); }

// The tip's distance to x_d (m), the series whose last 5 mm crossing is the reach time.
// (problems/4/run/scenario.hpp, which the programs' --test replay shares)
auto tip_error(Target target) {
  return [target](const p4::Sample& s) { return p4::tip_error(target, s); };
}

double reach_time(const p4::Result& r) { return r.summary.reach_time; }
double peak_torque(const p4::Result& r) { return r.summary.peak_torque; }

// The statistic `statistic` of the run toward `target` (`of` reads it from the run's Summary) in
// the student's run `mine` and the reference's, with the check's bound: what the test judges.
Judgement judgement(const std::string& statistic, Target target, const p4::Result& mine, double (*of)(const p4::Result&),
                    double bound, const std::string& unit) {
  Judgement j;
  j.statistic = statistic, j.yours = of(mine), j.bound = bound, j.unit = unit;
  j.reference = reference_statistic("4 " + p4::describe(target) + " " + statistic,
                                    [of, target] { return of(reference_run(target)); });
  return j;
}

void reaches(Target target, const Hw2Api& api, Check& check) {
  const Run& run_of_mine = run(api, target);
  const p4::Result& mine = run_of_mine.result;
  RunFigure f;
  f.quantity = "tip error |x - x_d| " + p4::describe(target);
  f.unit = "mm";
  f.unit_scale = 1e3;
  f.bound = p4::kReachTolerance;
  f.judged = "it must stay below the bound from 2 s on at the latest";
  f.judged_from = kReachBound;
  check.figure(run_figure(f, mine.samples, tip_error(target), "4 tip error " + p4::describe(target),
                          [target]() -> const auto& { return reference_run(target).samples; }));
  const p4::Result& plain = run_plain(target);
  if (!ran_to_the_end(check, mine.failure)) return;
  const std::string goal =
      std::string("the target 10 cm ") + (target == Target::kAlongZ0 ? "down " : "") + p4::describe(target);
  const std::vector<Judged> judged = {
      {judgement("time until the tip stays within 5 mm of x_d", target, mine, &reach_time, kReachBound, "s"),
       "Leaving the lock takes the potential a few tenths of a second, then the tip PD converges "
       "in about 1 s"},
      // The URDF's effort limit: a larger request is clamped by the simulation.
      {judgement("peak joint torque", target, mine, &peak_torque, kEffortLimit, "N m"),
       "Near the singularity Lambda_v must drop the singular directions, or its huge inertia "
       "asks for huge torques"}};
  if (mine.summary.reach_time < 0.0) {
    // A run that went to its end without reaching: nothing, and the page shows what it judged,
    // as every other failed run's (its reach time never came: infinite, "never").
    check.that(false, "the tip never stayed within 5 mm of " + goal + " (final error " +
                          millimetres(mine.summary.final_error) + ")");
    for (Judged j : judged) {
      if (j.judgement.yours < 0.0) {
        j.judgement.yours = std::numeric_limits<double>::infinity();
        j.judgement.yours_text = "never (final error " + millimetres(mine.summary.final_error) + ")";
      }
      check.show(j.judgement);
    }
    return;
  }
  judge_run(check, run_of_mine.pin, "your controller " + p4::describe(target), "v", judged);
  // The contrast that makes the exercise: from the same start the plain controller either
  // never reaches x_d or only with torques beyond the limits. It does not depend on the
  // student's code: a failure here is a broken scenario, reported as such.
  const bool plain_fails = plain.summary.reach_time < 0.0 || plain.summary.reach_time > kReachBound ||
                           plain.summary.clamped_steps > 0;
  check.that(plain_fails, "scenario error: the plain controller reached " + goal + " in " +
                              seconds(plain.summary.reach_time) + " without saturating");
}

}  // namespace
}  // namespace p4_graded

Problem problem_4() {
  using namespace p4_graded;
  namespace id = test_id::p4;
  // Questions i-iv (analysis.cpp), then v.
  std::vector<GradedTest> tests = analysis_tests();
  const std::vector<GradedTest> v = {
              {id::kLaw, "v. the controller applies Jv^T F + N^T (A (-kpj (q - q_d) - kvj dq) + g) with each target's "
               "potential",
               3,
               "For Z0 the potential's minimum is the retracted arm, q_d[2] = kRetractedElbow; for Y0 it is "
               "joint 1 at q_d[0] = kTurnedJoint1; the other joints keep q_d = q.",
               law},
              {id::kSimAlongZ0,
               "v. in simulation the tip reaches 10 cm down along Z0 within 2 s where the plain controller "
               "saturates",
               3,
               "Along Z0 the arm must retract first: only the elbow potential, projected by N^T, gets it out of "
               "the lock.",
               [](const Hw2Api& api, Check& check) { reaches(Target::kAlongZ0, api, check); }, "hw2-p4 z"},
              {id::kSimAlongY0,
               "v. in simulation the tip reaches 10 cm along Y0 within 2 s where the plain controller never "
               "does",
               3,
               "Along Y0 the arm's plane must first turn to face Y0: drive joint 1 toward 90 deg in the null "
               "space.",
               [](const Hw2Api& api, Check& check) { reaches(Target::kAlongY0, api, check); }, "hw2-p4 y"},
  };
  tests.insert(tests.end(), v.begin(), v.end());
  return {"4", "3R elbow arm: singularities, analysed and controlled (simulated)", tests};
}

namespace oracle {
Eigen::Vector3d law_4(hw2::p4::Target target, const hw2::p4::State& s, const hw2::p4::Goal& goal) {
  return p4_graded::expected_torque(target, s, goal);
}
}  // namespace oracle

}  // namespace opspace::grading
