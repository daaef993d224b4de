/// @file spatial.hpp
/// Spatial (6D) algebra used inside the library, everything in the base frame and about the
/// base origin O (Featherstone's "spatial vectors at the origin"):
///   motion m = [v_O; w]  (linear velocity of the body point at O, angular velocity),
///   force  f = [f; n_O]  (force, moment about O); power = m . f.
/// Private to lib/src.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "opspace/model.hpp"

namespace opspace::spatial {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// [x]: the cross-product matrix, [x] y = x cross y.
inline Eigen::Matrix3d skew(const Eigen::Vector3d& x) {
  Eigen::Matrix3d X;
  X << 0.0, -x.z(), x.y(), x.z(), 0.0, -x.x(), -x.y(), x.x(), 0.0;
  return X;
}

/// m1 xm m2 = [w1 x v2 + v1 x w2; w1 x w2]: rate of change of motion m2 moving with m1.
inline Vector6d cross_motion(const Vector6d& m1, const Vector6d& m2) {
  Vector6d r;
  r.head<3>() = m1.tail<3>().cross(m2.head<3>()) + m1.head<3>().cross(m2.tail<3>());
  r.tail<3>() = m1.tail<3>().cross(m2.tail<3>());
  return r;
}

/// m xf f = [w x f; w x n + v x f]: rate of change of force f moving with m.
inline Vector6d cross_force(const Vector6d& m, const Vector6d& f) {
  Vector6d r;
  r.head<3>() = m.tail<3>().cross(f.head<3>());
  r.tail<3>() = m.tail<3>().cross(f.tail<3>()) + m.head<3>().cross(f.head<3>());
  return r;
}

/// Spatial inertia about O of mass m with centre c and rotational inertia Ic about c, all in
/// the base frame: [[m 1, -m [c]], [m [c], Ic - m [c][c]]]  (momentum h = I [v_O; w]).
inline Matrix6d inertia_at_origin(double m, const Eigen::Vector3d& c, const Eigen::Matrix3d& Ic) {
  const Eigen::Matrix3d C = skew(c);
  Matrix6d I;
  I.topLeftCorner<3, 3>() = m * Eigen::Matrix3d::Identity();
  I.topRightCorner<3, 3>() = -m * C;
  I.bottomLeftCorner<3, 3>() = m * C;
  I.bottomRightCorner<3, 3>() = Ic - m * C * C;
  return I;
}

/// I m for the spatial inertia inertia_at_origin(m, c, Ic), applied without forming it:
///   I [v; w] = [m (v - c x w); Ic w + c x m (v - c x w)].
inline Vector6d apply_inertia(double m, const Eigen::Vector3d& c, const Eigen::Matrix3d& Ic,
                              const Vector6d& motion) {
  Vector6d f;
  f.head<3>() = m * (motion.head<3>() - c.cross(motion.tail<3>()));
  f.tail<3>() = Ic * motion.tail<3>() + c.cross(f.head<3>());
  return f;
}

/// Spatial inertia of body i about O at its current pose oMi: c = oMi com, I = R Ic R^T.
inline Matrix6d body_inertia(const Inertia& in, const Eigen::Isometry3d& oMi) {
  const Eigen::Matrix3d& R = oMi.linear();
  return inertia_at_origin(in.mass, oMi * in.com, R * in.inertia * R.transpose());
}

/// Joint motion subspace in the base frame: revolute about unit axis a through point p:
/// S = [p x a; a]; prismatic along a: S = [a; 0].
inline Vector6d motion_subspace(const Body& body, const Eigen::Isometry3d& oMi) {
  const Eigen::Vector3d a = oMi.linear() * body.axis;
  Vector6d S;
  if (body.type == JointType::kRevolute) {
    S << oMi.translation().cross(a), a;
  } else {
    S << a, Eigen::Vector3d::Zero();
  }
  return S;
}

}  // namespace opspace::spatial
