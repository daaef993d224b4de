/// @file algorithms/kinematics.hpp
/// Poses, point Jacobians J0 = [Jv; Jw] and Jdot qdot, all expressed in the base frame.
/// Call forward_kinematics() first: the other functions read data.body_pose. Source: R.
/// Featherstone, Rigid Body Dynamics Algorithms, Springer 2008, chapter 4 (joint models and
/// their motion subspaces S_i); J0 and its blocks are the problem set's.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "opspace/model/model.hpp"

namespace opspace {

using Matrix6Xd = Eigen::Matrix<double, 6, Eigen::Dynamic>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

/// Body poses oMi = oMparent * placement * joint(q_i) for configuration q (data.body_pose), and
/// each joint's motion subspace S_i in the base frame (data.S).
void forward_kinematics(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q);

/// Pose of frame `frame` in the base frame.
Eigen::Isometry3d frame_pose(const Model& model, const Data& data, int frame);

/// Position x = oMf * p of a point p given in frame `frame`.
Eigen::Vector3d point_position(const Model& model, const Data& data, int frame,
                               const Eigen::Vector3d& p);

/// J0 = [Jv; Jw] (6 x dof) of point p on frame `frame`: [v; w] = J0 qdot.
void point_jacobian(const Model& model, const Data& data, int frame, const Eigen::Vector3d& p,
                    Eigen::Ref<Matrix6Xd> J0);

/// [v; w] = J0 qdot of point p on frame `frame`.
Vector6d point_velocity(const Model& model, const Data& data, int frame, const Eigen::Vector3d& p,
                        const Eigen::Ref<const Eigen::VectorXd>& qdot);

/// Jdot qdot (6): the point's acceleration [vdot; wdot] when qdd = 0.
Vector6d point_jacobian_dot_times_qdot(const Model& model, Data& data, int frame,
                                       const Eigen::Vector3d& p,
                                       const Eigen::Ref<const Eigen::VectorXd>& q,
                                       const Eigen::Ref<const Eigen::VectorXd>& qdot);

}  // namespace opspace
