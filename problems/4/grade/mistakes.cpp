// Known mistakes of problem 4. Each replaces one function, or wraps the law it is given (the
// reference solutions, or the grader's oracle).
#include <problems/4/contract.hpp>
#include "opspace/algorithms/linalg.hpp"
#include <problems/4/run/scenario.hpp>

#include <cmath>

#include "judge/mistakes.hpp"
#include <problems/4/tests.hpp>

namespace opspace::grading {

namespace p4_mistakes {  // named: problems share a unity unit (problems/CMakeLists.txt)
namespace {

using hw2::p4::Directions;
using hw2::p4::Goal;
using hw2::p4::Kinematics;
using hw2::p4::State;
using hw2::p4::Target;

// ii. The singular directions taken from V (joint space) instead of U (the tip's space).
Directions singular_directions_from_v(const Kinematics& k) {
  const Svd svd_of_Jv = svd(k.Jv, Eigen::ComputeFullV);  // the library's, not a new JacobiSVD
  const Eigen::Vector3d s = svd_of_Jv.sigma;
  int rank = 0;
  for (int i = 0; i < 3; ++i) rank += s(i) > hw2::p4::kTolerance * s(0) ? 1 : 0;
  Directions d;
  d.count = 3 - rank;
  d.u.leftCols(d.count) = svd_of_Jv.V.rightCols(d.count);
  return d;
}

// iv. The second-order test over every joint motion instead of the self-motions: H_u != 0.
SingularityType type_over_all_joint_motions(const Kinematics& k, const Eigen::Vector3d& u) {
  const double sigma_max = svd(k.Jv, 0).sigma(0);
  if ((k.Jv.transpose() * u).norm() > hw2::p4::kTolerance * sigma_max) return SingularityType::kNone;
  const Eigen::Matrix3d H_u = u(0) * k.H[0] + u(1) * k.H[1] + u(2) * k.H[2];
  return H_u.cwiseAbs().maxCoeff() > hw2::p4::kTolerance * sigma_max ? SingularityType::kTypeI
                                                                       : SingularityType::kTypeII;
}

// iv. A route, not a slip: the stub's answer with the solution set's types pasted in for its
// configuration theta = (0, 90 deg, 0) (Z0 Type I, Y0 Type II, X0 none), kNone everywhere else.
SingularityType types_looked_up(const Kinematics& k, const Eigen::Vector3d& u) {
  const bool problem_set_q = (k.q - scenarios::p4::singular_q()).norm() < 1e-9;
  if (problem_set_q && std::abs(std::abs(u(2)) - 1.0) < 1e-9) return SingularityType::kTypeI;
  if (problem_set_q && std::abs(std::abs(u(1)) - 1.0) < 1e-9) return SingularityType::kTypeII;
  return SingularityType::kNone;  // the stub's answer
}

using Law = Fn<decltype(hw2::p4::control)>;

// v. The Z0 potential with its minimum at the stretched arm (q_d[2] = 0): it pulls the elbow
// into the lock instead of out of it.
Eigen::Vector3d z0_potential_stretches(const Law& law, Target target, const State& s, const Goal& goal) {
  const Eigen::Vector3d tau = law(target, s, goal);
  if (target != Target::kAlongZ0) return tau;
  // The reference pulls joint 3 toward kRetractedElbow; move that minimum to 0.
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  shift(2) = -goal.kpj * hw2::p4::kRetractedElbow;  // -kpj (q3 - 0) = -kpj (q3 - q3r) - kpj q3r
  return tau + s.N.transpose() * (s.A * shift);
}

}  // namespace
}  // namespace p4_mistakes

std::vector<Mistake> mistakes_4() {
  using namespace p4_mistakes;
  namespace id = test_id::p4;
  return {
      {"singular directions from the right singular vectors V",
       "a singular direction lives in the tip's space: the columns of U (Jv = U S V^T) whose sigma vanishes",
       [](Hw2Api& api) { api.p4.singular_directions = &singular_directions_from_v; },
       {id::kDirections}},
      // Every overhead lock then looks Type I: joint 1 combined with joint 2 does move the tip
      // along the plane's normal at second order, but that motion is not a self-motion.
      {"Type I/II tested over all joint motions, not the self-motions",
       "the type tests the self-motions only: C_u = Nb^T H_u Nb with Nb a basis of the null space of Jv",
       [](Hw2Api& api) { api.p4.singularity_type = &type_over_all_joint_motions; },
       {id::kStraightUpTypes, id::kTypesElsewhere}},
      // Right at theta = (0, 90 deg, 0), wrong at the same arm turned about Z0 (its overhead lock is
      // no longer Y0) and at every other singular configuration.
      {"the types looked up for theta = (0, 90 deg, 0) alone (Z0 Type I, Y0 Type II) and kNone elsewhere",
       "the type of u at the configuration given: kNone unless u^T Jv = 0, then Type I if some self-motion moves "
       "the tip along u at second order (C_u = Nb^T H_u Nb != 0), else Type II",
       [](Hw2Api& api) { api.p4.singularity_type = &types_looked_up; },
       {id::kStraightUpTypes, id::kTypesElsewhere}},
      // Turning joint 1 does not unlock a stretched elbow, and retracting the arm does not turn
      // its plane: neither target is reached.
      {"the Z0 and Y0 potentials swapped",
       "for Z0 the potential retracts the elbow (q_d[2] = kRetractedElbow); for Y0 it turns joint 1 (q_d[0] = kTurnedJoint1)",
       [](Hw2Api& api) {
         api.p4.control = [law = api.p4.control](Target target, const State& s, const Goal& g) {
           return law(target == Target::kAlongZ0 ? Target::kAlongY0 : Target::kAlongZ0, s, g);
         };
       },
       {id::kLaw, id::kSimAlongZ0, id::kSimAlongY0}},
      {"the Z0 potential's minimum at the stretched arm",
       "the Z0 potential's minimum is the retracted arm, q_d[2] = kRetractedElbow, which leads out of the lock",
       [](Hw2Api& api) {
         api.p4.control = [law = api.p4.control](Target target, const State& s, const Goal& g) {
           return z0_potential_stretches(law, target, s, g);
         };
       },
       {id::kLaw, id::kSimAlongZ0}},
  };
}

}  // namespace opspace::grading
