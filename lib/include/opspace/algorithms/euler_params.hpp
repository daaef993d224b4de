/// @file algorithms/euler_params.hpp
/// Euler parameters (unit quaternions) as the problem set writes them, scalar first:
/// lambda = (lambda_0, lambda_1, lambda_2, lambda_3), lambda_0 = cos(theta/2) and
/// (lambda_1, lambda_2, lambda_3) = sin(theta/2) u for a rotation by theta about the unit axis u.
///
/// The orientation part of the operational coordinates x = [x_p; x_r] is x_r = lambda. Its rate
/// is lambda_dot = E_r(lambda) omega, omega the angular velocity in the base frame, and
///   x_dot = E(x) [v; omega],   E = diag(I3, E_r)                       (problem set, 2(b))
///
///   E_r = 1/2 [[-l1, -l2, -l3],
///              [ l0,  l3, -l2],
///              [-l3,  l0,  l1],
///              [ l2, -l1,  l0]]
///
/// The columns of E_r are orthogonal, each of norm |lambda| / 2, so E_r^T E_r = |lambda|^2/4 I
/// and E_r^+ = (E_r^T E_r)^-1 E_r^T = 4 E_r^T / |lambda|^2, i.e. 4 E_r^T for unit lambda.
/// Also E_r^T lambda = 0: a rotation cannot change |lambda|.
///
/// lambda and -lambda are the same orientation; same_side() chooses between them.
#pragma once

#include <Eigen/Core>

namespace opspace {

using Vector7d = Eigen::Matrix<double, 7, 1>;
using Matrix43d = Eigen::Matrix<double, 4, 3>;
using Matrix34d = Eigen::Matrix<double, 3, 4>;
using Matrix76d = Eigen::Matrix<double, 7, 6>;
using Matrix67d = Eigen::Matrix<double, 6, 7>;

/// E_r(lambda) (4x3): lambda_dot = E_r omega, omega in the base frame.
Matrix43d euler_rate_matrix(const Eigen::Ref<const Eigen::Vector4d>& lambda);

/// E_r^+ = 4 E_r^T / |lambda|^2 (3x4): omega = E_r^+ lambda_dot. Throws std::invalid_argument
/// for lambda = 0.
Matrix34d euler_rate_matrix_pinv(const Eigen::Ref<const Eigen::Vector4d>& lambda);

/// E(x) = diag(I3, E_r(lambda)) (7x6): x_dot = E [v; omega], x = [x_p; lambda].
Matrix76d representation_matrix(const Eigen::Ref<const Eigen::Vector4d>& lambda);

/// E^+ = diag(I3, E_r^+(lambda)) (6x7): [v; omega] = E^+ x_dot.
Matrix67d representation_matrix_pinv(const Eigen::Ref<const Eigen::Vector4d>& lambda);

/// The orientation error delta_phi = E_r^+(lambda) (lambda - lambda_d), with E_r^+ at the
/// CURRENT lambda (problem set, 2(c)). For unit lambda, lambda_d it equals
/// 2 vec(lambda * conj(lambda_d)) = 2 sin(theta/2) u, where theta u is the rotation vector of
/// R R_d^T (the rotation from the desired to the current orientation, in the base frame), as
/// long as lambda . lambda_d >= 0 (same_side()): for small errors delta_phi ~ theta u.
Eigen::Vector3d orientation_error(const Eigen::Ref<const Eigen::Vector4d>& lambda,
                                  const Eigen::Ref<const Eigen::Vector4d>& lambda_d);

/// The Euler parameters of a rotation matrix, scalar first, with lambda_0 >= 0. R must be a
/// rotation (orthonormal, det +1) to rounding; the result is normalised.
Eigen::Vector4d euler_parameters(const Eigen::Ref<const Eigen::Matrix3d>& R);

/// The rotation matrix of Euler parameters lambda (normalised first).
Eigen::Matrix3d rotation_matrix(const Eigen::Ref<const Eigen::Vector4d>& lambda);

/// lambda or -lambda, whichever lies on the side of `reference` (lambda . reference >= 0):
/// the same orientation, expressed continuously with the reference.
Eigen::Vector4d same_side(const Eigen::Ref<const Eigen::Vector4d>& lambda,
                          const Eigen::Ref<const Eigen::Vector4d>& reference);

/// Rotation angle (rad, in [0, pi]) between the orientations lambda and lambda_d: the angle
/// of R R_d^T, 2 atan2(|vec(lambda * conj(lambda_d))|, |lambda . lambda_d|).
double rotation_angle_between(const Eigen::Ref<const Eigen::Vector4d>& lambda,
                              const Eigen::Ref<const Eigen::Vector4d>& lambda_d);

}  // namespace opspace
