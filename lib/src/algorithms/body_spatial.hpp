/// @file body_spatial.hpp
/// The spatial algebra of math/spatial.hpp applied to the Model's bodies: a body's inertia
/// about the base origin O, sums and products of such inertias, a joint's motion subspace.
/// Private to lib/src.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "../math/spatial.hpp"
#include "opspace/model/model.hpp"

namespace opspace::spatial {

/// Body i's inertia about O at its pose oMi = (R, t): c = R com + t, h = m c and, by parallel
/// axes, I = R Ic R^T + m [c]^T [c] = R Ic R^T + (h . c) 1 - h c^T.
inline void body_inertia(const Inertia& in, const Eigen::Isometry3d& oMi, SpatialInertia& out) {
  const Eigen::Matrix3d R = oMi.linear();
  const Eigen::Vector3d c = R * in.com + oMi.translation();
  out.m = in.mass;
  out.h = in.mass * c;
  out.I.noalias() = (R * in.inertia).lazyProduct(R.transpose());
  out.I.noalias() -= out.h * c.transpose();
  out.I.diagonal().array() += out.h.dot(c);
}

/// The inertia of two bodies together: the sum of each of m, h and I.
inline void add_inertia(SpatialInertia& to, const SpatialInertia& from) {
  to.m += from.m;
  to.h += from.h;
  to.I += from.I;
}

/// I [v; w] = [m v - h x w; h x v + I w]: the momentum of motion [v; w] (no 6x6 matrix).
inline Vector6d apply_inertia(const SpatialInertia& in, const Vector6d& motion) {
  Vector6d f;
  f.head<3>() = in.m * motion.head<3>() - in.h.cross(motion.tail<3>());
  f.tail<3>() = in.h.cross(motion.head<3>()) + in.I * motion.tail<3>();
  return f;
}

/// Joint motion subspace in the base frame, for the body at rotation R and position t:
/// revolute about unit axis a = R axis through t: S = [t x a; a]; prismatic along a: S = [a; 0].
inline Vector6d motion_subspace(const Body& body, const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  const Eigen::Vector3d a = R * body.axis;
  Vector6d S;
  if (body.type == JointType::kRevolute) {
    S << t.cross(a), a;
  } else {
    S << a, Eigen::Vector3d::Zero();
  }
  return S;
}

}  // namespace opspace::spatial
