// Graded tests of problem 1a. Every expected value comes from an oracle with a reason:
// the closed forms of lib/include/opspace/algorithms/pp_robot.hpp (derived by hand from the problem
// set and cross-checked in tests/lib/test_pp_robot.cpp), the general inverses of linalg.hpp
// at random Jacobians and weights, or the closed form of a 2x2 projector written out below.
// Every test that takes inputs asks the problem set's inputs as one case among random ones, so
// that an answer hard-coded for m1 = 10, m2 = 5 or J = [1 1] cannot pass.
#include "opspace/algorithms/linalg.hpp"
#include "opspace/algorithms/pp_robot.hpp"

#include "judge/graded_suite.hpp"
#include <problems/1a/tests.hpp>
#include "grader/suite/random.hpp"

namespace opspace::grading {

namespace p1a_graded {  // named: problems share a unity unit (problems/CMakeLists.txt)
namespace {

namespace pp = opspace::pp;
using testing::Random;

// 2x2 formulas in double precision: round-off is ~1e-15; 1e-9 accepts any correct way of
// computing them (explicit inverse, solve, closed form) and rejects every wrong formula.
constexpr double kTol = 1e-9;
constexpr int kTrials = 5;

std::string masses(double m1, double m2) {
  return "m1 = " + std::to_string(m1) + ", m2 = " + std::to_string(m2);
}

Eigen::RowVector2d random_jacobian(Random& rng) {
  // Entries away from zero, so that J J^T >= 0.5 and every inverse is well conditioned.
  auto entry = [&rng] { return (rng.uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0) * rng.uniform(0.5, 2.0); };
  return Eigen::RowVector2d(entry(), entry());
}

Eigen::Matrix2d random_spd(Random& rng) {
  const Eigen::Matrix2d W = rng.spd(2, 0.5);
  return 0.5 * (W + W.transpose());
}

// The oracle of the three projector tests, independent of the formula I - J_inv J the student
// writes. For J = [a b], null(J) is the line of n = (-b, a). A right inverse J_inv (J J_inv = 1)
// splits the plane into null(J) and the line of J_inv; I - J_inv J is the projector onto null(J)
// along J_inv: it keeps n (J n = 0) and sends J_inv to J_inv - J_inv (J J_inv) = 0. The unique
// such projector is n m^T / (m . n) with m = (-J_inv(1), J_inv(0)), orthogonal to J_inv
// (m . n = J J_inv = 1 up to round-off). For J+ = J^T / |J|^2, m is along n and the projector is
// the orthogonal n n^T / |n|^2.
Eigen::Matrix2d projector_onto_nullspace_along(const Eigen::RowVector2d& J, const Eigen::Vector2d& J_inv) {
  const Eigen::Vector2d n(-J(1), J(0));
  const Eigen::Vector2d m(-J_inv(1), J_inv(0));
  return n * m.transpose() / m.dot(n);
}

void degrees_of_freedom(const Hw2Api& api, Check& check) {
  const hw2::p1a::DegreesOfFreedom dof = api.p1a.degrees_of_freedom();
  check.near("degrees of freedom of the task", 1.0, dof.task, 0.0,
             "The task is one coordinate: the end-effector position along X0");
  check.near("degrees of freedom of the robot", 2.0, dof.robot, 0.0,
             "The robot has two joints, d1 and d2");
  check.that(dof.redundant,
             "redundant: expected true, computed false. A robot with more joints than its task "
             "needs has a null space of self-motions");
}

void mass_matrix(const Hw2Api& api, Check& check) {
  Random rng(seed_for(101));
  for (int trial = 0; trial < kTrials; ++trial) {
    const double m1 = rng.uniform(1.0, 20.0), m2 = rng.uniform(1.0, 20.0);
    if (!check.near("A(" + masses(m1, m2) + ")", pp::mass_matrix(m1, m2), api.p1a.mass_matrix(m1, m2),
                    kTol,
                    "Link 2 rides on link 1: its speed is d1dot + d2dot, so m2 appears in every "
                    "entry and couples the joints"))
      return;
  }
}

void task_jacobian(const Hw2Api& api, Check& check) {
  check.near("J", pp::task_jacobian(), api.p1a.task_jacobian(), kTol,
             "x_ee = d1 + d2, so each joint moves the end-effector one for one");
}

void pseudo_inverse(const Hw2Api& api, Check& check) {
  if (!check.near("J+ for J = [1 1]", pp::pseudo_inverse(), api.p1a.pseudo_inverse(pp::task_jacobian()),
                  kTol, "J+ = J^T (J J^T)^-1 shares the motion equally between the joints"))
    return;
  Random rng(seed_for(102));
  for (int trial = 0; trial < kTrials; ++trial) {
    const Eigen::RowVector2d J = random_jacobian(rng);
    if (!check.near("J+ for J = " + format(J), opspace::pseudo_inverse(J), api.p1a.pseudo_inverse(J),
                    kTol, "J+ = J^T (J J^T)^-1 must hold for any full-rank J, not only [1 1]"))
      return;
  }
}

void pseudo_inverse_projector(const Hw2Api& api, Check& check) {
  const Eigen::RowVector2d J = pp::task_jacobian();
  if (!check.near("I - J+ J for J = [1 1]", pp::pseudo_inverse_nullspace(),
                  api.p1a.nullspace_projector(J, pp::pseudo_inverse()), kTol,
                  "The projector keeps the joint motions that leave x_ee still: d1 and d2 opposite"))
    return;
  Random rng(seed_for(108));
  for (int trial = 0; trial < kTrials; ++trial) {
    const Eigen::RowVector2d Jr = random_jacobian(rng);
    const Eigen::Vector2d J_pinv = Jr.transpose() / Jr.squaredNorm();  // J J^T is the number |J|^2
    if (!check.near("I - J+ J for J = " + format(Jr) + ", J+ = " + format(J_pinv),
                    projector_onto_nullspace_along(Jr, J_pinv), api.p1a.nullspace_projector(Jr, J_pinv), kTol,
                    "I - J+ J is the orthogonal projector onto the null space of J, the line of (-J(1), J(0)): "
                    "it must hold for any J, not only [1 1]"))
      return;
  }
}

void weighted_inverse(const Hw2Api& api, Check& check) {
  Random rng(seed_for(103));
  const Eigen::RowVector2d J = pp::task_jacobian();
  for (int trial = 0; trial < kTrials; ++trial) {
    const double w1 = rng.uniform(0.2, 10.0), w2 = rng.uniform(0.2, 10.0);
    const Eigen::Matrix2d W = Eigen::Vector2d(w1, w2).asDiagonal();
    if (!check.near("J# for W = diag(" + std::to_string(w1) + ", " + std::to_string(w2) + ")",
                    pp::weighted_inverse(w1, w2), api.p1a.weighted_inverse(J, W), kTol,
                    "J# = W^-1 J^T (J W^-1 J^T)^-1: the heavier-weighted joint moves less"))
      return;
  }
  for (int trial = 0; trial < kTrials; ++trial) {
    const Eigen::RowVector2d Jr = random_jacobian(rng);
    const Eigen::Matrix2d W = random_spd(rng);
    if (!check.near("J# for J = " + format(Jr) + ", W = " + format(W), opspace::weighted_inverse(Jr, W),
                    api.p1a.weighted_inverse(Jr, W), kTol,
                    "the formula must hold for a full (non-diagonal) weight and any J"))
      return;
  }
}

void weighted_projector(const Hw2Api& api, Check& check) {
  Random rng(seed_for(104));
  const Eigen::RowVector2d J = pp::task_jacobian();
  for (int trial = 0; trial < kTrials; ++trial) {
    const double w1 = rng.uniform(0.2, 10.0), w2 = rng.uniform(0.2, 10.0);
    if (!check.near("I - J# J for w1 = " + std::to_string(w1) + ", w2 = " + std::to_string(w2),
                    pp::weighted_inverse_nullspace(w1, w2),
                    api.p1a.nullspace_projector(J, pp::weighted_inverse(w1, w2)), kTol,
                    "The projector is I - J_inv J (n x n), in this order: I - J^T J_inv^T is its "
                    "transpose, the projector that acts on torques, and differs when J# is not J+"))
      return;
  }
  for (int trial = 0; trial < kTrials; ++trial) {
    const Eigen::RowVector2d Jr = random_jacobian(rng);
    const Eigen::Vector2d J_sharp = opspace::weighted_inverse(Jr, random_spd(rng));
    if (!check.near("I - J# J for J = " + format(Jr) + ", J# = " + format(J_sharp),
                    projector_onto_nullspace_along(Jr, J_sharp), api.p1a.nullspace_projector(Jr, J_sharp), kTol,
                    "I - J# J keeps the self-motions (J dq = 0) and removes the motion along J#: it must hold "
                    "for any J and any right inverse"))
      return;
  }
}

void inertia_weighted_inverse(const Hw2Api& api, Check& check) {
  Random rng(seed_for(105));
  const Eigen::RowVector2d J = pp::task_jacobian();
  for (int trial = 0; trial < kTrials; ++trial) {
    const double m1 = rng.uniform(1.0, 20.0), m2 = rng.uniform(1.0, 20.0);
    if (!check.near("Jbar for " + masses(m1, m2), pp::inertia_weighted_inverse(),
                    api.p1a.inertia_weighted_inverse(J, pp::mass_matrix(m1, m2)), kTol,
                    "Jbar = A^-1 J^T (J A^-1 J^T)^-1 = [0 1]^T for any masses: moving x_ee "
                    "requires moving m2 anyway, and moving m1 as well would only cost energy"))
      return;
  }
  for (int trial = 0; trial < kTrials; ++trial) {
    const Eigen::RowVector2d Jr = random_jacobian(rng);
    const Eigen::Matrix2d A = random_spd(rng);
    if (!check.near("Jbar for J = " + format(Jr) + ", A = " + format(A),
                    opspace::dynamically_consistent_inverse(Jr, A),
                    api.p1a.inertia_weighted_inverse(Jr, A), kTol,
                    "the formula must hold for any mass matrix and any J"))
      return;
  }
}

void inertia_weighted_projector(const Hw2Api& api, Check& check) {
  if (!check.near("I - Jbar J for J = [1 1], Jbar = [0 1]^T", pp::inertia_weighted_nullspace(),
                  api.p1a.nullspace_projector(pp::task_jacobian(), pp::inertia_weighted_inverse()), kTol,
                  "With Jbar = [0 1]^T the self-motion moves d1 and compensates with d2 = -d1"))
    return;
  Random rng(seed_for(109));
  for (int trial = 0; trial < kTrials; ++trial) {
    const Eigen::RowVector2d Jr = random_jacobian(rng);
    const Eigen::Matrix2d A = random_spd(rng);
    const Eigen::Vector2d Jbar = opspace::dynamically_consistent_inverse(Jr, A);
    if (!check.near("I - Jbar J for J = " + format(Jr) + ", A = " + format(A) + ", Jbar = " + format(Jbar),
                    projector_onto_nullspace_along(Jr, Jbar), api.p1a.nullspace_projector(Jr, Jbar), kTol,
                    "I - Jbar J keeps the self-motions (J dq = 0) and removes the motion along Jbar: it must "
                    "hold for any mass matrix and any J"))
      return;
  }
}

void inverse_kinematics_family(const Hw2Api& api, Check& check) {
  Random rng(seed_for(106));
  for (int trial = 0; trial < kTrials; ++trial) {
    const Eigen::RowVector2d J = random_jacobian(rng);
    const Eigen::Vector2d J_inv = opspace::weighted_inverse(J, random_spd(rng));
    const double dx = rng.uniform(-0.5, 0.5);
    const Eigen::Vector2d dq0 = rng.vector(2);
    const Eigen::Vector2d expected = J_inv * dx + opspace::nullspace_projector(J, J_inv) * dq0;
    if (!check.near("dq for dx = " + std::to_string(dx) + ", dq0 = " + format(dq0), expected,
                    api.p1a.inverse_kinematics_step(J, J_inv, dx, dq0), kTol,
                    "dq = J_inv dx + (I - J_inv J) dq0: the task motion plus a self-motion that "
                    "does not move x_ee"))
      return;
  }
}

void split_displacement(const Hw2Api& api, Check& check) {
  Random rng(seed_for(107));
  for (int trial = 0; trial < kTrials; ++trial) {
    const double m1 = rng.uniform(1.0, 20.0), m2 = rng.uniform(1.0, 20.0);
    const double dx = rng.uniform(0.01, 0.5);
    const hw2::p1a::DisplacementSplit split = api.p1a.split_displacement(m1, m2, dx);
    const std::string at = " for dx = " + std::to_string(dx) + ", " + masses(m1, m2);
    if (!check.near("dq with J+" + at, pp::pseudo_inverse() * dx, split.with_pseudo_inverse, kTol,
                    "The pseudo-inverse shares the motion equally: each joint moves dx / 2"))
      return;
    if (!check.near("dq with Jbar" + at, pp::inertia_weighted_inverse() * dx, split.with_inertia_weighted,
                    kTol, "The inertia-weighted inverse moves only the lighter, outer link: d2 = dx"))
      return;
  }
}

}  // namespace
}  // namespace p1a_graded

Problem problem_1a() {
  using namespace p1a_graded;
  namespace id = test_id::p1a;
  return {"1a",
          "PP robot: weighted instantaneous inverse kinematics",
          {
              {id::kRedundant, "i. the task needs one degree of freedom, the robot has two: it is redundant", 1,
               "Count the task coordinates and the joints.", degrees_of_freedom},
              {id::kMassMatrix, "ii. the mass matrix reproduces the kinetic energy of both links", 3,
               "Expand T = 1/2 m1 d1dot^2 + 1/2 m2 (d1dot + d2dot)^2 and match 1/2 qdot^T A qdot.",
               mass_matrix},
              {id::kJacobian, "iii. the task Jacobian maps joint rates to the end-effector rate", 1,
               "Differentiate x_ee = d1 + d2.", task_jacobian},
              {id::kPseudoInverse, "iv. the pseudo-inverse is J^T (J J^T)^-1", 3,
               "J J^T is 1x1 here: a number to divide by.", pseudo_inverse},
              {id::kPseudoInverseProjector,
               "iv. I - J+ J keeps only the self-motions that leave the end-effector still", 2,
               "The identity minus the outer product J_inv J, 2x2.", pseudo_inverse_projector},
              {id::kWeightedInverse, "v. the weighted inverse is W^-1 J^T (J W^-1 J^T)^-1", 3,
               "Invert the weight: a joint with a large weight should move little.", weighted_inverse},
              {id::kWeightedProjector, "v. I - J# J is the weighted null-space projector", 2,
               "Mind the order: I - J_inv J, not its transpose.", weighted_projector},
              {id::kConsistentInverse, "vi. the inertia-weighted inverse moves only the light link", 3,
               "It is the weighted inverse with W = A.", inertia_weighted_inverse},
              {id::kConsistentProjector, "vi. I - Jbar J is the dynamically consistent projector", 1,
               "Same projector formula, with Jbar as the right inverse.", inertia_weighted_projector},
              {id::kFamily, "iv-vi. every inverse gives the family dq = J_inv dx + (I - J_inv J) dq0", 2,
               "Task motion plus projected self-motion.", inverse_kinematics_family},
              {id::kSharing, "vi. J+ shares dx equally between the joints, Jbar moves only joint 2", 2,
               "Apply your J+ and your Jbar (W = A(m1, m2)) to dx with dq0 = 0.", split_displacement},
          }};
}

}  // namespace opspace::grading
