// The grader's answers to every function of the problem set, gathered as a Hw2Api: the
// closed forms and general formulas its tests compare with (p1a.cpp: pp_robot.hpp and
// linalg.hpp), the laws written out in p1b.cpp ... p4.cpp, and the library's singularity
// analysis for problem 4's questions i-iv.
#include <opspace/algorithms/euler_params.hpp>
#include <opspace/algorithms/linalg.hpp>
#include <opspace/algorithms/pp_robot.hpp>
#include <opspace/algorithms/singularity.hpp>

#include "oracles.hpp"
#include "support/problem2.hpp"

namespace opspace::grading::oracle {

namespace {

hw2::p4::Directions first_columns(const Eigen::Matrix3d& U, int first, int count) {
  hw2::p4::Directions d;
  d.count = count;
  d.u.leftCols(count) = U.middleCols(first, count);
  return d;
}

Eigen::Matrix<double, 9, 3> stacked(const hw2::p4::Kinematics& k) {
  Eigen::Matrix<double, 9, 3> H;
  H << k.H[0], k.H[1], k.H[2];
  return H;
}

// The answers, named as the contracts' functions (answer::p1a::mass_matrix answers
// hw2::p1a::mass_matrix): reference_api() takes one for each row of the problems' tables, so a
// function without an answer here fails to compile.
namespace answer {

namespace p1a {
using hw2::p1a::DegreesOfFreedom;
using hw2::p1a::DisplacementSplit;
const auto degrees_of_freedom = [] { return DegreesOfFreedom{1, 2, true}; };
const auto mass_matrix = [](double m1, double m2) { return pp::mass_matrix(m1, m2); };
const auto task_jacobian = [] { return pp::task_jacobian(); };
const auto pseudo_inverse = [](const Eigen::RowVector2d& J) { return Eigen::Vector2d(opspace::pseudo_inverse(J)); };
const auto weighted_inverse = [](const Eigen::RowVector2d& J, const Eigen::Matrix2d& W) {
  return Eigen::Vector2d(opspace::weighted_inverse(J, W));
};
const auto inertia_weighted_inverse = [](const Eigen::RowVector2d& J, const Eigen::Matrix2d& A) {
  return Eigen::Vector2d(opspace::dynamically_consistent_inverse(J, A));
};
const auto nullspace_projector = [](const Eigen::RowVector2d& J, const Eigen::Vector2d& J_inv) {
  return Eigen::Matrix2d(opspace::nullspace_projector(J, J_inv));
};
const auto inverse_kinematics_step = [](const Eigen::RowVector2d& J, const Eigen::Vector2d& J_inv, double dx,
                                        const Eigen::Vector2d& dq0) {
  return Eigen::Vector2d(J_inv * dx + opspace::nullspace_projector(J, J_inv) * dq0);
};
const auto split_displacement = [](double m1, double m2, double dx) {
  const Eigen::RowVector2d J = pp::task_jacobian();
  DisplacementSplit split;
  split.with_pseudo_inverse = opspace::pseudo_inverse(J) * dx;
  split.with_inertia_weighted = opspace::dynamically_consistent_inverse(J, pp::mass_matrix(m1, m2)) * dx;
  return split;
};
}  // namespace p1a

namespace p1b {
const auto control = &law_1b;
}  // namespace p1b

namespace p2 {
const auto desired_acceleration = &testing::problem_set_xddot_d;
const auto desired_twist_acceleration = [](const Eigen::Vector4d& lambda, const hw2::p2::Vector7d& xddot_d) {
  return hw2::p2::Vector6d(representation_matrix_pinv(lambda) * xddot_d);
};
const auto control = &law_2;
}  // namespace p2

namespace p3 {
const auto motion_selection = &omega;
const auto force_selection = &omega_bar;
const auto control = &law_3;
}  // namespace p3

namespace p4 {
using hw2::p4::Kinematics;
const auto degrees_of_freedom = [](const Kinematics& k) { return directions(k.Jv).rank; };
const auto singular_directions = [](const Kinematics& k) {
  const Directions3 d = directions(k.Jv);
  return first_columns(d.U, d.rank, 3 - d.rank);
};
const auto moving_directions = [](const Kinematics& k) {
  const Directions3 d = directions(k.Jv);
  return first_columns(d.U, 0, d.rank);
};
const auto rotation_axes = [](const Kinematics& k) {
  const Directions3 d = directions(k.Jw);
  return first_columns(d.U, 0, d.rank);
};
const auto singularity_type = [](const Kinematics& k, const Eigen::Vector3d& u) {
  return opspace::singularity_type(k.Jv, stacked(k), u);
};
const auto control = &law_4;
}  // namespace p4

}  // namespace answer

}  // namespace

Hw2Api reference_api() {
  Hw2Api api;
  api.identity = 2;
#define OPSPACE_ANSWER_SLOT(problem, code, Code, name) api.problem.name = answer::problem::name;
  OPSPACE_FUNCTIONS(OPSPACE_ANSWER_SLOT)
#undef OPSPACE_ANSWER_SLOT
  return api;
}

}  // namespace opspace::grading::oracle
