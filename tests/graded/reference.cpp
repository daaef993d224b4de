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

namespace p1a = hw2::p1a;
namespace p4 = hw2::p4;

p4::Directions first_columns(const Eigen::Matrix3d& U, int first, int count) {
  p4::Directions d;
  d.count = count;
  d.u.leftCols(count) = U.middleCols(first, count);
  return d;
}

Eigen::Matrix<double, 9, 3> stacked(const p4::Kinematics& k) {
  Eigen::Matrix<double, 9, 3> H;
  H << k.H[0], k.H[1], k.H[2];
  return H;
}

}  // namespace

Hw2Api reference_api() {
  Hw2Api api;
  api.identity = 2;
  api.p1a.degrees_of_freedom = [] { return p1a::DegreesOfFreedom{1, 2, true}; };
  api.p1a.mass_matrix = [](double m1, double m2) { return pp::mass_matrix(m1, m2); };
  api.p1a.task_jacobian = [] { return pp::task_jacobian(); };
  api.p1a.pseudo_inverse = [](const Eigen::RowVector2d& J) { return Eigen::Vector2d(opspace::pseudo_inverse(J)); };
  api.p1a.weighted_inverse = [](const Eigen::RowVector2d& J, const Eigen::Matrix2d& W) {
    return Eigen::Vector2d(opspace::weighted_inverse(J, W));
  };
  api.p1a.inertia_weighted_inverse = [](const Eigen::RowVector2d& J, const Eigen::Matrix2d& A) {
    return Eigen::Vector2d(opspace::dynamically_consistent_inverse(J, A));
  };
  api.p1a.nullspace_projector = [](const Eigen::RowVector2d& J, const Eigen::Vector2d& J_inv) {
    return Eigen::Matrix2d(opspace::nullspace_projector(J, J_inv));
  };
  api.p1a.inverse_kinematics_step = [](const Eigen::RowVector2d& J, const Eigen::Vector2d& J_inv, double dx,
                                       const Eigen::Vector2d& dq0) {
    return Eigen::Vector2d(J_inv * dx + opspace::nullspace_projector(J, J_inv) * dq0);
  };
  api.p1a.split_displacement = [](double m1, double m2, double dx) {
    const Eigen::RowVector2d J = pp::task_jacobian();
    p1a::DisplacementSplit split;
    split.with_pseudo_inverse = opspace::pseudo_inverse(J) * dx;
    split.with_inertia_weighted = opspace::dynamically_consistent_inverse(J, pp::mass_matrix(m1, m2)) * dx;
    return split;
  };
  api.p1b.control = &law_1b;
  api.p2.desired_acceleration = &testing::problem_set_xddot_d;
  api.p2.desired_twist_acceleration = [](const Eigen::Vector4d& lambda, const hw2::p2::Vector7d& xddot_d) {
    return hw2::p2::Vector6d(representation_matrix_pinv(lambda) * xddot_d);
  };
  api.p2.control = &law_2;
  api.p3.motion_selection = &omega;
  api.p3.force_selection = &omega_bar;
  api.p3.control = &law_3;
  api.p4.degrees_of_freedom = [](const p4::Kinematics& k) { return directions(k.Jv).rank; };
  api.p4.singular_directions = [](const p4::Kinematics& k) {
    const Directions3 d = directions(k.Jv);
    return first_columns(d.U, d.rank, 3 - d.rank);
  };
  api.p4.moving_directions = [](const p4::Kinematics& k) {
    const Directions3 d = directions(k.Jv);
    return first_columns(d.U, 0, d.rank);
  };
  api.p4.rotation_axes = [](const p4::Kinematics& k) {
    const Directions3 d = directions(k.Jw);
    return first_columns(d.U, 0, d.rank);
  };
  api.p4.singularity_type = [](const p4::Kinematics& k, const Eigen::Vector3d& u) {
    return opspace::singularity_type(k.Jv, stacked(k), u);
  };
  api.p4.control = &law_4;
  return api;
}

}  // namespace opspace::grading::oracle
