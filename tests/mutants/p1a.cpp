// Known-wrong implementations of problem 1a.
#include <Eigen/Dense>

#include "mutants.hpp"

namespace opspace::mutants {

namespace {

// A = diag(m1 + m2, m2): the coupling term m2 d1dot d2dot of the kinetic energy forgotten.
Eigen::Matrix2d mass_matrix_without_coupling(double m1, double m2) {
  return Eigen::Vector2d(m1 + m2, m2).asDiagonal();
}

// J+ = J^T: the normalisation (J J^T)^-1 forgotten.
Eigen::Vector2d pseudo_inverse_unnormalised(const Eigen::RowVector2d& J) { return J.transpose(); }

// J# = W J^T (J W J^T)^-1: the weight used where its inverse belongs.
Eigen::Vector2d weighted_inverse_with_w(const Eigen::RowVector2d& J, const Eigen::Matrix2d& W) {
  const Eigen::Vector2d W_Jt = W * J.transpose();
  return W_Jt / J.dot(W_Jt);
}

// N = I - J^T J_inv^T: the transpose of the projector (the one that acts on torques).
Eigen::Matrix2d projector_transposed(const Eigen::RowVector2d& J, const Eigen::Vector2d& J_inv) {
  return Eigen::Matrix2d::Identity() - J.transpose() * J_inv.transpose();
}

// Question vi answered with J+ twice: the inertia-weighted split never computed.
hw2::p1a::DisplacementSplit split_with_pseudo_inverse_only(double, double, double dx) {
  hw2::p1a::DisplacementSplit split;
  split.with_pseudo_inverse = Eigen::Vector2d(0.5, 0.5) * dx;
  split.with_inertia_weighted = split.with_pseudo_inverse;
  return split;
}

}  // namespace

std::vector<Mutant> p1a_mutants() {
  return {
      {"A without the coupling term m2 off the diagonal",
       [](grading::Hw2Api& api) { api.p1a.mass_matrix = &mass_matrix_without_coupling; },
       {"ii. the mass matrix reproduces the kinetic energy of both links"}},
      {"J+ = J^T, without (J J^T)^-1",
       [](grading::Hw2Api& api) { api.p1a.pseudo_inverse = &pseudo_inverse_unnormalised; },
       {"iv. the pseudo-inverse is J^T (J J^T)^-1"}},
      {"J# built with W instead of W^-1",
       [](grading::Hw2Api& api) { api.p1a.weighted_inverse = &weighted_inverse_with_w; },
       {"v. the weighted inverse is W^-1 J^T (J W^-1 J^T)^-1"}},
      // J+ J is symmetric, so only the projectors of J# and Jbar reveal the transpose.
      {"projector written as I - J^T J_inv^T",
       [](grading::Hw2Api& api) { api.p1a.nullspace_projector = &projector_transposed; },
       {"v. I - J# J is the weighted null-space projector",
        "vi. I - Jbar J is the dynamically consistent projector"}},
      {"question vi answered with J+ for both splits",
       [](grading::Hw2Api& api) { api.p1a.split_displacement = &split_with_pseudo_inverse_only; },
       {"vi. J+ shares dx equally between the joints, Jbar moves only joint 2"}},
  };
}

}  // namespace opspace::mutants
