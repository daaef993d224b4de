#include "opspace/algorithms/euler_params.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

namespace opspace {

Matrix43d euler_rate_matrix(const Eigen::Ref<const Eigen::Vector4d>& lambda) {
  const double l0 = lambda(0), l1 = lambda(1), l2 = lambda(2), l3 = lambda(3);
  Matrix43d Er;
  Er << -l1, -l2, -l3,
         l0,  l3, -l2,
        -l3,  l0,  l1,
         l2, -l1,  l0;
  return 0.5 * Er;
}

Matrix34d euler_rate_matrix_pinv(const Eigen::Ref<const Eigen::Vector4d>& lambda) {
  const double n2 = lambda.squaredNorm();
  if (!(n2 > 0.0)) throw std::invalid_argument("euler_rate_matrix_pinv: lambda is zero (or not finite)");
  // E_r^T E_r = |lambda|^2 / 4 I  =>  E_r^+ = (E_r^T E_r)^-1 E_r^T = 4 E_r^T / |lambda|^2
  return (4.0 / n2) * euler_rate_matrix(lambda).transpose();
}

Matrix76d representation_matrix(const Eigen::Ref<const Eigen::Vector4d>& lambda) {
  Matrix76d E = Matrix76d::Zero();
  E.topLeftCorner<3, 3>().setIdentity();
  E.bottomRightCorner<4, 3>() = euler_rate_matrix(lambda);
  return E;
}

Matrix67d representation_matrix_pinv(const Eigen::Ref<const Eigen::Vector4d>& lambda) {
  Matrix67d Ep = Matrix67d::Zero();
  Ep.topLeftCorner<3, 3>().setIdentity();
  Ep.bottomRightCorner<3, 4>() = euler_rate_matrix_pinv(lambda);
  return Ep;
}

Eigen::Vector3d orientation_error(const Eigen::Ref<const Eigen::Vector4d>& lambda,
                                  const Eigen::Ref<const Eigen::Vector4d>& lambda_d) {
  return euler_rate_matrix_pinv(lambda) * (lambda - lambda_d);
}

Eigen::Vector4d euler_parameters(const Eigen::Ref<const Eigen::Matrix3d>& R) {
  // Eigen's conversion picks the largest of the four |lambda_i| to divide by (Shepperd), so it
  // stays accurate at every angle, including theta near pi where lambda_0 -> 0.
  const Eigen::Quaterniond q(R);
  Eigen::Vector4d lambda(q.w(), q.x(), q.y(), q.z());
  lambda.normalize();
  return lambda(0) < 0.0 ? Eigen::Vector4d(-lambda) : lambda;
}

Eigen::Matrix3d rotation_matrix(const Eigen::Ref<const Eigen::Vector4d>& lambda) {
  return Eigen::Quaterniond(lambda(0), lambda(1), lambda(2), lambda(3)).normalized().toRotationMatrix();
}

Eigen::Vector4d same_side(const Eigen::Ref<const Eigen::Vector4d>& lambda,
                          const Eigen::Ref<const Eigen::Vector4d>& reference) {
  return lambda.dot(reference) < 0.0 ? Eigen::Vector4d(-lambda) : Eigen::Vector4d(lambda);
}

double rotation_angle_between(const Eigen::Ref<const Eigen::Vector4d>& lambda,
                              const Eigen::Ref<const Eigen::Vector4d>& lambda_d) {
  // lambda * conj(lambda_d) = (lambda . lambda_d, -2 E_r(lambda)^T lambda_d) (problem-set E_r)
  const double c = std::abs(lambda.dot(lambda_d));
  const double s = (2.0 * euler_rate_matrix(lambda).transpose() * lambda_d).norm();
  return 2.0 * std::atan2(s, c);
}

}  // namespace opspace
