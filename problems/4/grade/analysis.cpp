// Graded tests of problem 4's analysis (questions i-iv): at theta = (0, 90 deg, 0) and at random
// members of the arm's singular families, against closed forms of the geometry (derived below
// and in guide.md), from the library's Jv, Jw and Hessians of the tip.
#include "opspace/math/constants.hpp"
#include "opspace/model/urdf.hpp"
#include <problems/4/run/scenario.hpp>

#include <cmath>
#include <cstdio>

#include "analysis.hpp"
#include <problems/4/tests.hpp>
#include "grader/suite/random.hpp"

namespace opspace::grading {

namespace p4_graded {

namespace p4 = opspace::scenarios::p4;

const Model& rrr() {
  static const Model model = load_urdf(robot_path(p4::kRobotFile));
  return model;
}

std::string deg(const Eigen::Vector3d& q) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "theta = (%.1f, %.1f, %.1f) deg", q(0) / kDeg, q(1) / kDeg, q(2) / kDeg);
  return buffer;
}

}  // namespace p4_graded

namespace p4_analysis {  // named: problems share a unity unit (problems/CMakeLists.txt)
namespace {

namespace p4 = opspace::scenarios::p4;
using hw2::p4::Kinematics;
using opspace::SingularityType;
using p4_graded::deg;
using p4_graded::rrr;

// Directions come from 3x3 SVDs: round-off ~1e-15. At these configurations the vanishing
// singular values are round-off and the others at least ~0.1, so any correct method returns
// the subspaces to ~1e-12; 1e-8 accepts them all and rejects every wrong subspace (whose
// projector differs at order 1).
constexpr double kDirTol = 1e-8;

Kinematics at(const Eigen::Vector3d& q) {
  Data data(rrr());
  return p4::kinematics(rrr(), data, q);
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

}  // namespace
}  // namespace p4_analysis

std::vector<GradedTest> p4_graded::analysis_tests() {
  using namespace p4_analysis;
  namespace id = test_id::p4;
  return {
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
  };
}

}  // namespace opspace::grading
