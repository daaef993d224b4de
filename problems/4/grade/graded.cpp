// Graded tests of problem 4. Two kinds:
// - the analysis (questions i-iv): at theta = (0, 90 deg, 0) and at random members of the arm's
//   singular families, against closed forms of the geometry (derived below and in
//   guide.md), from the library's Jv, Jw and Hessians of the tip;
// - question v: the law at random states against the equation written out here, and the
//   closed loop on the Bullet simulation, beside the plain operational-space controller,
//   measured only on the problem set's law: every tick of the run is compared with the law's
//   oracle at the same State and Goal (law_pin.hpp).
#include <opspace/math/constants.hpp>
#include <problems/4/run/scenario.hpp>
#include <opspace/model/urdf.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "simulated_runs.hpp"
#include "answers.hpp"
#include "oracles.hpp"
#include "run_figure.hpp"
#include "graded_suite.hpp"
#include "problems/4/tests.hpp"
#include "support/random.hpp"

namespace opspace::grading {

namespace p4_graded {  // named: problems share a unity unit (problems/CMakeLists.txt)
namespace {

namespace p4 = opspace::scenarios::p4;
using hw2::p4::Kinematics;
using hw2::p4::Target;
using opspace::SingularityType;

// Directions come from 3x3 SVDs: round-off ~1e-15. At these configurations the vanishing
// singular values are round-off and the others at least ~0.1, so any correct method returns
// the subspaces to ~1e-12; 1e-8 accepts them all and rejects every wrong subspace (whose
// projector differs at order 1).
constexpr double kDirTol = 1e-8;
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

const Model& rrr() {
  static const Model model = load_urdf(robot_path(p4::kRobotFile));
  return model;
}

Kinematics at(const Eigen::Vector3d& q) {
  Data data(rrr());
  return p4::kinematics(rrr(), data, q);
}

std::string deg(const Eigen::Vector3d& q) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "theta = (%.1f, %.1f, %.1f) deg", q(0) / kDeg, q(1) / kDeg, q(2) / kDeg);
  return buffer;
}

// A configuration of the arm with the closed forms of its singular directions. The links are
// 0.5 m each, the shoulder 0.35 m up; r = 0.5 (cos q2 + cos(q2 + q3)) is the tip's distance
// from the joint-1 axis. Joints 2 and 3 move the tip in the arm's vertical plane; joint 1
// moves it along the plane's normal n = (-sin q1, cos q1, 0), by r.
struct Case {
  std::string what;
  Eigen::Vector3d q;
  Eigen::MatrixXd singular;  // 3 x m closed-form singular directions
  std::vector<SingularityType> types;  // of each column
  bool straight_up = false;  // theta2 = 90 deg, theta3 = 0: the problem set's arm, turned about Z0 or not
};

Eigen::Vector3d plane_normal(double q1) { return Eigen::Vector3d(-std::sin(q1), std::cos(q1), 0.0); }

std::vector<Case> cases() {
  std::vector<Case> out;
  // The problem set: straight up. Only X0 moves the tip; Z0 elbow lock (Type I), Y0 overhead
  // lock (Type II).
  out.push_back({"the problem set's configuration", p4::singular_q(),
                 (Eigen::MatrixXd(3, 2) << 0, 0, 0, 1, 1, 0).finished(),
                 {SingularityType::kTypeI, SingularityType::kTypeII}, true});
  testing::Random rng(seed_for(401));
  for (int k = 0; k < 2; ++k) {
    // Elbow lock alone: q3 = 0, |q2| <= 60 deg so r = cos q2 >= 0.5. The tip cannot move along
    // the stretched arm e = (cos q1 cos q2, sin q1 cos q2, sin q2); folding the elbow (a
    // self-motion) pulls it back along e at second order: Type I.
    const double q1 = rng.uniform(-kPi, kPi), q2 = rng.uniform(-60, 60) * kDeg;
    out.push_back({"a stretched arm (elbow lock)", Eigen::Vector3d(q1, q2, 0.0),
                   Eigen::Vector3d(std::cos(q1) * std::cos(q2), std::sin(q1) * std::cos(q2), std::sin(q2)),
                   {SingularityType::kTypeI}});
    // Overhead lock alone: q3 = 180 deg - 2 q2 puts the tip on the joint-1 axis (r = 0) with the
    // elbow bent by 20-80 deg. The only self-motion, joint 1, spins the arm about the vertical
    // through the tip: the tip never moves along n, at any order: Type II.
    const double a = rng.uniform(-kPi, kPi), b = rng.uniform(50, 80) * kDeg;
    out.push_back({"a bent arm with its tip above the base (overhead lock)", Eigen::Vector3d(a, b, kPi - 2.0 * b),
                   plane_normal(a), {SingularityType::kTypeII}});
    // Both, with joint 1 anywhere: the problem set's configuration turned about Z0.
    const double c = rng.uniform(-kPi, kPi);
    Eigen::MatrixXd both(3, 2);
    both << Eigen::Vector3d::UnitZ(), plane_normal(c);
    out.push_back({"the straight-up arm turned about Z0", Eigen::Vector3d(c, 90 * kDeg, 0.0), both,
                   {SingularityType::kTypeI, SingularityType::kTypeII}, true});
  }
  // Regular: elbow bent by 70-100 deg, tip at least 0.1 m from the joint-1 axis (r = 0.47 m, 0.11 m).
  out.push_back({"a regular configuration", Eigen::Vector3d(0.7, 20 * kDeg, 70 * kDeg), Eigen::MatrixXd(3, 0), {}});
  out.push_back({"a regular configuration", Eigen::Vector3d(-2.0, -30 * kDeg, -100 * kDeg), Eigen::MatrixXd(3, 0), {}});
  return out;
}

Eigen::Matrix3d projector(const Eigen::Ref<const Eigen::MatrixXd>& U) { return U.lazyProduct(U.transpose()); }

// The student's directions as a projector; false (and a finding) if count is impossible.
bool projector_of(const hw2::p4::Directions& d, const std::string& what, Check& check, Eigen::Matrix3d& P) {
  if (!check.that(d.count >= 0 && d.count <= 3, what + ": count = " + std::to_string(d.count) + " is not 0-3"))
    return false;
  P = projector(d.u.leftCols(d.count));
  return true;
}

void degrees_of_freedom(const Hw2Api& api, Check& check) {
  for (const Case& c : cases()) {
    const double expected = 3.0 - static_cast<double>(c.singular.cols());
    if (!check.near("tip degrees of freedom at " + deg(c.q) + " (" + c.what + ")", expected,
                    api.p4.degrees_of_freedom(at(c.q)), 0.0,
                    "Count the singular values of Jv above kTolerance * sigma_max: the rank of Jv"))
      return;
  }
}

void singular_directions(const Hw2Api& api, Check& check) {
  for (const Case& c : cases()) {
    const std::string where = deg(c.q) + " (" + c.what + ")";
    const hw2::p4::Directions d = api.p4.singular_directions(at(c.q));
    if (!check.near("number of singular directions at " + where, static_cast<double>(c.singular.cols()), d.count,
                    0.0, "One per vanishing singular value of Jv"))
      return;
    Eigen::Matrix3d P;
    if (!projector_of(d, "singular directions", check, P)) return;
    // u u^T does not depend on the sign of u, nor on the basis of a 2-D subspace.
    if (!check.near("u u^T of the singular directions at " + where, projector(c.singular), P, kDirTol,
                    "The singular directions are the left singular vectors (columns of U) whose singular "
                    "value vanishes, unit and orthogonal"))
      return;
  }
}

void orthogonal_directions(const Hw2Api& api, Check& check) {
  for (const Case& c : cases()) {
    const std::string where = deg(c.q) + " (" + c.what + ")";
    const Kinematics k = at(c.q);
    Eigen::Matrix3d P;
    const hw2::p4::Directions moving = api.p4.moving_directions(k);
    if (!projector_of(moving, "moving directions", check, P)) return;
    // range(Jv) is the orthogonal complement of the singular directions.
    if (!check.near("u u^T of the moving directions at " + where,
                    Eigen::Matrix3d::Identity() - projector(c.singular), P, kDirTol,
                    "The tip moves along the directions orthogonal to the singular ones: the columns of U "
                    "with non-vanishing singular values"))
      return;
    // Joint 1 turns about Z0, joints 2 and 3 about (sin q1, -cos q1, 0): the tip rotates about
    // these two axes only, whatever the configuration (Jw has rank 2; no roll about the arm).
    const hw2::p4::Directions axes = api.p4.rotation_axes(k);
    if (!projector_of(axes, "rotation axes", check, P)) return;
    Eigen::MatrixXd W(3, 2);
    W << Eigen::Vector3d::UnitZ(), -plane_normal(c.q(0));
    if (!check.near("u u^T of the rotation axes at " + where, projector(W), P, kDirTol,
                    "Angular motion: the range of Jw, spanned by the joint axes Z0 and (sin q1, -cos q1, 0)"))
      return;
  }
}

const char* name(SingularityType t) {
  switch (t) {
    case SingularityType::kNone: return "kNone";
    case SingularityType::kTypeI: return "kTypeI";
    case SingularityType::kTypeII: return "kTypeII";
  }
  return "?";
}

bool label(const Hw2Api& api, const Kinematics& k, const Eigen::Vector3d& u, SingularityType expected,
           const std::string& where, const std::string& meaning, Check& check) {
  // Both signs of u: a direction's type does not depend on its sign (C_-u = -C_u).
  for (double sign : {1.0, -1.0}) {
    const SingularityType got = api.p4.singularity_type(k, sign * u);
    if (!check.that(got == expected, "type of u = " + format(sign * u) + " at " + where + ": expected " +
                                         name(expected) + ", computed " + name(got) + ". " + meaning))
      return false;
  }
  return true;
}

// The problem set's configuration first, then the same arm turned about Z0 by a random angle c
// (cases()), so that types looked up for theta = (0, 90 deg, 0) alone cannot pass. Turning the
// whole arm about Z0 turns its geometry with it: Z0 stays the elbow lock, the overhead lock is
// the normal n = (-sin c, cos c, 0) of the arm's plane (Y0 at c = 0), and the tip moves along
// the plane's horizontal (cos c, sin c, 0) (X0 at c = 0).
void types_of_the_straight_up_arm(const Hw2Api& api, Check& check) {
  for (const Case& c : cases()) {
    if (!c.straight_up) continue;
    const Kinematics k = at(c.q);
    const std::string where = deg(c.q) + " (" + c.what + ")";
    if (!label(api, k, Eigen::Vector3d::UnitZ(), SingularityType::kTypeI, where,
               "Folding the elbow is a self-motion (Jv dq = 0 at first order) that lowers the tip: the elbow "
               "lock is Type I",
               check))
      return;
    if (!label(api, k, plane_normal(c.q(0)), SingularityType::kTypeII, where,
               "No self-motion (joint 1, or the elbow folding in the arm's plane) moves the tip across the plane, "
               "even at second order: the overhead lock is Type II",
               check))
      return;
    if (!label(api, k, Eigen::Vector3d(std::cos(c.q(0)), std::sin(c.q(0)), 0.0), SingularityType::kNone, where,
               "The horizontal of the arm's plane is not singular: joints 2 and 3 move the tip along it", check))
      return;
  }
}

void types_elsewhere(const Hw2Api& api, Check& check) {
  for (const Case& c : cases()) {
    if (c.straight_up) continue;  // the previous test
    const std::string where = deg(c.q) + " (" + c.what + ")";
    const Kinematics k = at(c.q);
    for (Eigen::Index j = 0; j < c.singular.cols(); ++j) {
      const bool elbow = c.types[static_cast<std::size_t>(j)] == SingularityType::kTypeI;
      if (!label(api, k, c.singular.col(j), c.types[static_cast<std::size_t>(j)], where,
                 elbow ? "An elbow lock: folding the elbow retracts the tip along the stretched arm"
                       : "An overhead lock: the self-motion only spins the arm about the tip's vertical",
                 check))
        return;
    }
    // A direction the tip moves along is not singular: for the first singular column u, the
    // tip can move along any unit vector orthogonal to all singular ones.
    const Eigen::Matrix3d free = Eigen::Matrix3d::Identity() - projector(c.singular);
    Eigen::Index best = 0;
    free.colwise().norm().maxCoeff(&best);
    if (!label(api, k, free.col(best).normalized(), SingularityType::kNone, where,
               "A direction orthogonal to the singular ones is in range(Jv): not singular", check))
      return;
  }
}

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
  return {"4",
          "3R elbow arm: singularities, analysed and controlled (simulated)",
          {
              {id::kRank, "i. the tip has one degree of freedom at theta = (0, 90 deg, 0): the rank of Jv", 2,
               "Take the SVD of Jv and count the singular values above kTolerance * sigma_max.",
               degrees_of_freedom},
              {id::kDirections,
               "ii. the singular directions are Y0 and Z0 at theta = (0, 90 deg, 0), the left null space of Jv "
               "elsewhere",
               3,
               "A singular direction is a direction of the tip's space, so it is a column of U (Jv = U S V^T), "
               "not of V, which lives in joint space.",
               singular_directions},
              {id::kDirectionLeft,
               "iii. X0 is the only direction left for the tip, which can still rotate about Y0 and Z0", 2,
               "The moving directions are the other columns of U; the rotation axes come from the SVD of Jw.",
               orthogonal_directions},
              {id::kStraightUpTypes,
               "iv. the straight-up arm (theta = (0, 90 deg, 0), or turned about Z0) has a Type I elbow lock along "
               "Z0 and a Type II overhead lock across its plane",
               2,
               "Test the self-motions only: the null-space basis Nb of Jv, then C = Nb^T H_u Nb, from the Kinematics "
               "given (the arm may be turned about Z0).",
               types_of_the_straight_up_arm},
              {id::kTypesElsewhere,
               "iv. a stretched elbow is a Type I singularity and a tip above the base a Type II one", 2,
               "The type is a property of the direction and the configuration: use H_u = sum_k u_k H[k] and the "
               "null space of Jv at that configuration.",
               types_elsewhere},
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
          }};
}

namespace oracle {
Eigen::Vector3d law_4(hw2::p4::Target target, const hw2::p4::State& s, const hw2::p4::Goal& goal) {
  return p4_graded::expected_torque(target, s, goal);
}
}  // namespace oracle

}  // namespace opspace::grading
