// Problem 4: the singularities of the 3R elbow arm, analysed (i-iv) and controlled (v).
// Run:    bash scripts/run hw2-p4            (questions i-iv at theta = (0, 90 deg, 0), then v)
// Grade:  bash scripts/grade --problem 4
//
// `k` holds the tip's kinematics at one configuration: k.q, the tip k.x, its Jacobians k.Jv
// and k.Jw (3x3), and the Hessians k.H[0..2] of its coordinates X0, Y0, Z0.
// Eigen::JacobiSVD<Eigen::Matrix3d> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV) gives
// svd.singularValues() (decreasing), svd.matrixU() and svd.matrixV().
// A singular value sigma_i <= kTolerance * sigma_max counts as zero.
#include <problems/4/contract.hpp>

namespace opspace::hw2::p4 {

int degrees_of_freedom(const Kinematics& k) {
  // i. The rank of Jv: how many singular values of Jv exceed kTolerance * sigma_max.
  // FILL ME IN
  return 0;
}

Directions singular_directions(const Kinematics& k) {
  // ii. Jv = U diag(sigma) V^T. The columns of U whose sigma vanishes are the directions u
  // with u^T Jv = 0: no joint velocity moves the tip along them.
  //   count = 3 - rank,  u.leftCols(count) = those columns of U
  // FILL ME IN
  return {};
}

Directions moving_directions(const Kinematics& k) {
  // iii. The other columns of U (sigma > kTolerance * sigma_max): they span range(Jv).
  // FILL ME IN
  return {};
}

Directions rotation_axes(const Kinematics& k) {
  // iii. The same for rotations: the columns of Jw's U with non-vanishing sigma.
  // FILL ME IN
  return {};
}

SingularityType singularity_type(const Kinematics& k, const Eigen::Vector3d& u) {
  // iv. kNone unless u^T Jv = 0 (|Jv^T u| <= kTolerance * sigma_max).
  // The self-motions dq_n (Jv dq_n = 0) are the columns Nb of V whose sigma vanishes (a Basis3:
  // at most 3 columns). They move the tip along u only at second order:
  // u . xdd = dq_n^T H_u dq_n, H_u = sum_k u_k H[k].
  //   C = Nb^T H_u Nb;   C != 0 (above kTolerance * sigma_max): Type I, otherwise Type II
  // FILL ME IN
  return SingularityType::kNone;
}

Eigen::Vector3d control(Target target, const State& s, const Goal& goal) {
  // v. The operational-space law with the singularity-robust s.Lambda_v, s.N, s.p, plus a
  // self-motion potential V = kpj/2 |q - q_d|^2 in the null space:
  //   F      = Lambda_v (-kpx (x - x_d) - kvx dx) + p
  //   Gamma  = Jv^T F + N^T (A (-kpj (q - q_d) - kvj dq) + g)
  // with q_d = q except, for kAlongZ0, q_d[2] = kRetractedElbow (a retracted arm) and, for
  // kAlongY0, q_d[0] = kTurnedJoint1 (joint 1 at 90 deg).
  // FILL ME IN
  return Eigen::Vector3d::Zero();
}

}  // namespace opspace::hw2::p4
