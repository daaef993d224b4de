// Problem 4, reference solution: the SVD of Jv and Jw, the second-order test of the types,
// and the singularity-robust operational-space law with a self-motion potential.
#include <problems/4/contract.hpp>

namespace opspace::hw2::p4 {

namespace {

// Number of singular values above kTolerance * sigma_max (sigma is sorted, decreasing).
int rank_of(const Eigen::Vector3d& sigma) {
  int rank = 0;
  for (int i = 0; i < 3; ++i) rank += sigma(i) > kTolerance * sigma(0) ? 1 : 0;
  return rank;
}

// The columns [first, first + count) of U.
Directions columns(const Eigen::Matrix3d& U, int first, int count) {
  Directions d;
  d.count = count;
  d.u.leftCols(count) = U.middleCols(first, count);
  return d;
}

}  // namespace

int degrees_of_freedom(const Kinematics& k) {
  return rank_of(Eigen::JacobiSVD<Eigen::Matrix3d>(k.Jv).singularValues());
}

Directions singular_directions(const Kinematics& k) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(k.Jv, Eigen::ComputeFullU);
  const int rank = rank_of(svd.singularValues());
  return columns(svd.matrixU(), rank, 3 - rank);  // left singular vectors of the zero sigmas
}

Directions moving_directions(const Kinematics& k) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(k.Jv, Eigen::ComputeFullU);
  return columns(svd.matrixU(), 0, rank_of(svd.singularValues()));
}

Directions rotation_axes(const Kinematics& k) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(k.Jw, Eigen::ComputeFullU);
  return columns(svd.matrixU(), 0, rank_of(svd.singularValues()));
}

SingularityType singularity_type(const Kinematics& k, const Eigen::Vector3d& u) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(k.Jv, Eigen::ComputeFullV);
  const double sigma_max = svd.singularValues()(0);
  if ((k.Jv.transpose() * u).norm() > kTolerance * sigma_max) return SingularityType::kNone;
  // The self-motions: right singular vectors of the vanishing singular values.
  const int rank = rank_of(svd.singularValues());
  const Basis3 Nb = svd.matrixV().rightCols(3 - rank);
  const Eigen::Matrix3d H_u = u(0) * k.H[0] + u(1) * k.H[1] + u(2) * k.H[2];
  const double curvature =  // the largest entry of C = Nb^T H_u Nb: second-order motion along u
      Nb.cols() > 0 ? (Nb.transpose() * H_u * Nb).cwiseAbs().maxCoeff() : 0.0;
  return curvature > kTolerance * sigma_max ? SingularityType::kTypeI : SingularityType::kTypeII;
}

Eigen::Vector3d control(Target target, const State& s, const Goal& goal) {
  // The minimum of the self-motion potential V = kpj/2 |q - q_d|^2: only one joint differs.
  Eigen::Vector3d q_d = s.q;
  if (target == Target::kAlongZ0) q_d(2) = kRetractedElbow;  // retract the arm: bend the elbow
  if (target == Target::kAlongY0) q_d(0) = kTurnedJoint1;    // turn the arm's plane to face Y0
  const Eigen::Vector3d F = s.Lambda_v * (-goal.kpx * (s.x - goal.x_d) - goal.kvx * s.dx) + s.p;
  const Eigen::Vector3d Gamma0 = s.A * (-goal.kpj * (s.q - q_d) - goal.kvj * s.dq) + s.g;
  return s.Jv.transpose() * F + s.N.transpose() * Gamma0;
}

}  // namespace opspace::hw2::p4
