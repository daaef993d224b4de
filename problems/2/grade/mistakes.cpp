// Known mistakes of problem 2. The law is written out with one mistake made; 2(a)'s mistake
// wraps the function it is given (the reference solutions, or the grader's oracle). Every
// simulated test pins the law at every tick of the run (law_pin.hpp): a mistake costs each
// behaviour test whose judged statistic it moves, and a slip that moves nothing a test judges
// costs the law test alone. The comments say what the run shows; its rubric (guide.md) lists
// the points each costs.
#include "opspace/algorithms/euler_params.hpp"
#include <problems/2/contract.hpp>
#include "opspace/math/constants.hpp"

#include <cmath>

#include "judge/mistakes.hpp"
#include <problems/2/tests.hpp>

namespace opspace::grading {

namespace p2_mistakes {  // named: problems share a unity unit (problems/CMakeLists.txt)
namespace {

using hw2::p2::Goal;
using hw2::p2::State;
using hw2::p2::Vector6d;
using hw2::p2::Vector7d;

// What each mutant gets wrong in the law.
struct Mistakes {
  bool no_feed_forward = false;          // [vdot_d; wdot_d] left out
  bool E_pinv_at_lambda_d = false;       // every E^+ evaluated at lambda_d
  bool delta_phi_flipped = false;        // delta_phi = E^+ (lambda_d - lambda)
  bool no_nullspace_damping = false;     // N0^T (A (-kvj dq) + g) without A (-kvj dq)
  bool damping_not_projected = false;    // A (-kvj dq) added without N0^T
  bool no_p = false;                     // F without p
};

Vector7d law(const State& s, const Goal& goal, const Mistakes& m) {
  const Eigen::Vector4d lambda_d = goal.x_d.tail<4>();
  const Matrix67d E_pinv = representation_matrix_pinv(m.E_pinv_at_lambda_d ? lambda_d : s.lambda);
  Vector6d error, twist;
  error << s.x_p - goal.x_d.head<3>(), E_pinv.bottomRightCorner<3, 4>() * (s.lambda - lambda_d);
  if (m.delta_phi_flipped) error.tail<3>() = -error.tail<3>();
  twist << s.v, s.w;
  const Vector6d feed_forward = m.no_feed_forward ? Vector6d::Zero() : Vector6d(E_pinv * goal.xddot_d);
  const Vector6d F = s.Lambda0 * (-goal.kpx * error - goal.kvx * (twist - E_pinv * goal.xdot_d) + feed_forward) +
                     (m.no_p ? Vector6d::Zero() : s.p);
  const Vector7d damping = s.A * (-goal.kvj * s.dq);
  Vector7d tau = s.J0.transpose() * F + s.N0.transpose() * s.g;
  if (m.damping_not_projected) {
    tau += damping;
  } else if (!m.no_nullspace_damping) {
    tau += s.N0.transpose() * damping;
  }
  return tau;
}

// The law with one mistake made: &with<&Mistakes::no_feed_forward> and so on.
template <bool Mistakes::*kMistake>
Vector7d with(const State& s, const Goal& goal) {
  Mistakes m;
  m.*kMistake = true;
  return law(s, goal, m);
}

// 2(a) with the chain rule half done: d^2/dt^2 sin(a) taken as cos(a) a'', the -sin(a) a'^2
// term forgotten (and likewise for cos(a)), subtracted from the given 2(a).
Vector7d without_a_dot_squared(const Fn<decltype(hw2::p2::desired_acceleration)>& right, double t) {
  const double w = 2 * kPi / 5, s = 1 / std::sqrt(2.0);
  const double a = kPi / 4 * std::cos(w * t), a_dot = -kPi / 4 * w * std::sin(w * t);
  Vector7d wrong = right(t);
  const double sin_term = -std::sin(a) * a_dot * a_dot, cos_term = -std::cos(a) * a_dot * a_dot;
  wrong.tail<4>() -= s * Eigen::Vector4d(sin_term, cos_term, sin_term, cos_term);
  return wrong;
}

}  // namespace
}  // namespace p2_mistakes

std::vector<Mistake> mistakes_2() {
  using namespace p2_mistakes;
  namespace id = test_id::p2;
  const std::vector<std::string> law_and_run = {id::kLaw, id::kSimPosition, id::kSimOrientation,
                                                id::kSimContinuous, id::kSimJointLimits, id::kSimSelfMotion};
  // A law that brakes or sags the task: the tracking and the joints' excursion move; lambda
  // stays continuous and the self-motion damped.
  const std::vector<std::string> law_and_tracking = {id::kLaw, id::kSimPosition, id::kSimOrientation,
                                                     id::kSimJointLimits};
  return {
      // The PD alone lags the trajectory: 3.9 mm RMS in position, 0.03 rad RMS in orientation
      // (closed forms in problems/2/grade/graded.cpp), and a joint goes 2.46 deg past its limit
      // against the reference's 1.95 deg (moved by 0.51 deg, a tenth of the 5 deg bound being
      // 0.5); lambda stays continuous and the self-motion damped.
      {"no feed-forward acceleration [vdot_d; wdot_d]",
       "the command is -kpx e - kvx (edot) + [vdot_d; wdot_d], with [vdot_d; wdot_d] = E^+ xddot_d from 2(b)",
       [](Hw2Api& api) { api.p2.control = &with<&Mistakes::no_feed_forward>; },
       law_and_tracking},
      // For unit Euler parameters delta_phi is the same at lambda_d (test_euler_params.cpp), and
      // E^+(lambda_d) xdot_d differs from E^+(lambda) xdot_d only to second order in the
      // tracking error: along the run the torque differs from the law's by 0.015 % at most and
      // every judged statistic stays where the reference's is. The law test, at random states
      // with lambda_d tenths away from lambda, sees it; the run's tests keep their points.
      {"E^+ evaluated at lambda_d instead of the current lambda",
       "every E^+ in the law is evaluated at the current s.lambda",
       [](Hw2Api& api) { api.p2.control = &with<&Mistakes::E_pinv_at_lambda_d>; },
       {id::kLaw}},
      // Positive orientation feedback: link7 turns away from lambda_d until the error reaches
      // 180 degrees (lambda flips), the arm swings far off its path and past joint limits.
      {"delta_phi with the wrong sign, E^+ (lambda_d - lambda)",
       "delta_phi = E_r^+ (lambda - lambda_d), so that -kpx delta_phi turns link7 back to lambda_d",
       [](Hw2Api& api) { api.p2.control = &with<&Mistakes::delta_phi_flipped>; },
       law_and_run},
      // The task is still tracked, but the elbow's self-motion is undamped: the arm's posture
      // wanders by tens of degrees per period; every other statistic stays where the law puts it.
      {"no null-space damping N0^T A (-kvj dq)",
       "the null-space term is N0^T (A (-kvj dq) + g): it damps the self-motion",
       [](Hw2Api& api) { api.p2.control = &with<&Mistakes::no_nullspace_damping>; },
       {id::kLaw, id::kSimSelfMotion}},
      // A (-kvj dq) unprojected damps the task motion too: the arm lags by centimetres.
      {"joint damping A (-kvj dq) added without the projector N0^T",
       "the joint damping goes through N0^T, so that it cannot act on the task",
       [](Hw2Api& api) { api.p2.control = &with<&Mistakes::damping_not_projected>; },
       law_and_tracking},
      // Without p the task sags under the share of gravity the task carries: link7 tracks
      // centimetres below its path, tilted, and the arm's joints take another path, past a limit.
      {"p, the gravity at the task, left out of the task force",
       "F = Lambda0 (...) + p, with p = Jbar0^T g; N0^T g alone compensates only the null space's share",
       [](Hw2Api& api) { api.p2.control = &with<&Mistakes::no_p>; },
       law_and_tracking},
      // The runs take xddot_d from the problem set's closed forms, not from the student's 2(a)
      // (problems/2/grade/graded.cpp): a wrong 2(a) costs its own test and nothing else.
      {"2(a) without the -sin(a) a'^2 term of the chain rule",
       "d^2/dt^2 sin(a) = cos(a) a'' - sin(a) a'^2 (and likewise for cos(a))",
       [](Hw2Api& api) {
         api.p2.desired_acceleration = [right = api.p2.desired_acceleration](double t) {
           return without_a_dot_squared(right, t);
         };
       },
       {id::kAcceleration}},
  };
}

}  // namespace opspace::grading
