/// @file algorithms/dynamics.hpp
/// Joint-space dynamics A(q) qdd + b(q, qdot) + g(q) = tau of a Model.
/// Each function fills its member of Data and returns a reference to it; none allocates.
/// Source: R. Featherstone, Rigid Body Dynamics Algorithms, Springer 2008 (RBDA): the
/// recursive Newton-Euler algorithm of section 5.3 and the composite-rigid-body algorithm of
/// section 6.2, in the spatial algebra of chapter 2 (lib/src/math/spatial.hpp).
#pragma once

#include <Eigen/Core>

#include "opspace/model/model.hpp"

namespace opspace {

/// A(q), the joint-space mass matrix, by the composite-rigid-body algorithm (data.A; RBDA 6.2).
const Eigen::MatrixXd& crba(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q);

/// g(q), the joint torques that balance gravity (data.g).
const Eigen::VectorXd& generalized_gravity(const Model& model, Data& data,
                                           const Eigen::Ref<const Eigen::VectorXd>& q);

/// A(q) and g(q) from a single forward-kinematics pass (data.A, data.g): what a control tick
/// needs, at the cost of one pass instead of two. Afterwards data holds the poses of q, as
/// after forward_kinematics(), for the functions of kinematics.hpp.
void mass_matrix_and_gravity(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q);

/// b(q, qdot), the Coriolis and centrifugal torques, by recursive Newton-Euler (data.b; RBDA 5.3).
const Eigen::VectorXd& coriolis_centrifugal(const Model& model, Data& data,
                                            const Eigen::Ref<const Eigen::VectorXd>& q,
                                            const Eigen::Ref<const Eigen::VectorXd>& qdot);

/// tau = A qdd + b + g, by recursive Newton-Euler (data.tau; RBDA 5.3).
const Eigen::VectorXd& rnea(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q,
                            const Eigen::Ref<const Eigen::VectorXd>& qdot,
                            const Eigen::Ref<const Eigen::VectorXd>& qdd);

/// qdd = A^-1 (tau - b - g) (data.qdd; data.A and data.A_factor are updated too).
/// Throws std::invalid_argument if A(q) is not positive definite.
const Eigen::VectorXd& forward_dynamics(const Model& model, Data& data,
                                        const Eigen::Ref<const Eigen::VectorXd>& q,
                                        const Eigen::Ref<const Eigen::VectorXd>& qdot,
                                        const Eigen::Ref<const Eigen::VectorXd>& tau);

}  // namespace opspace
