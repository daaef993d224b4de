/// @file spatial.hpp
/// Spatial (6D) algebra used inside the library, everything in the base frame and about the
/// base origin O (R. Featherstone, Rigid Body Dynamics Algorithms, Springer 2008, chapter 2:
/// Plucker coordinates taken at the base origin):
///   motion m = [v_O; w]  (linear velocity of the body point at O, angular velocity),
///   force  f = [f; n_O]  (force, moment about O); power = m . f.
/// The math floor: Eigen only, nothing of the Model (algorithms/body_spatial.hpp applies it to
/// the Model's bodies). Private to lib/src.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

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

/// I m for the spatial inertia about O of mass m with centre c and rotational inertia Ic about
/// c, all in the base frame, applied without forming it:
///   I [v; w] = [m (v - c x w); Ic w + c x m (v - c x w)].
inline Vector6d apply_inertia(double m, const Eigen::Vector3d& c, const Eigen::Matrix3d& Ic,
                              const Vector6d& motion) {
  Vector6d f;
  f.head<3>() = m * (motion.head<3>() - c.cross(motion.tail<3>()));
  f.tail<3>() = Ic * motion.tail<3>() + c.cross(f.head<3>());
  return f;
}

/// R * Rot(axis, angle), in place, for a unit axis in R's frame. About a coordinate axis (+-x,
/// +-y, +-z: every joint of the course's robots) only two columns change, by a plane rotation:
/// for axis k and (i, j) = (k + 1, k + 2) mod 3, r_i' = c r_i + s r_j, r_j' = c r_j - s r_i. That
/// is 12 multiplications where Rodrigues' matrix and a 3x3 product take about 45.
inline void rotate_about_axis(Eigen::Matrix3d& R, const Eigen::Vector3d& axis, double angle) {
  int k = -1;
  if (axis.y() == 0.0 && axis.z() == 0.0) k = 0;
  else if (axis.x() == 0.0 && axis.z() == 0.0) k = 1;
  else if (axis.x() == 0.0 && axis.y() == 0.0) k = 2;
  if (k < 0) {
    R = R * Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    return;
  }
  const double a = angle * axis(k);  // axis(k) = +-1
  const double s = std::sin(a), c = std::cos(a);
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const Eigen::Vector3d ri = R.col(i), rj = R.col(j);
  R.col(i) = c * ri + s * rj;
  R.col(j) = c * rj - s * ri;
}

}  // namespace opspace::spatial
