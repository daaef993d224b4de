// Problem 1b, reference solution: the laws exactly as the problem set writes them.
#include <problems/1b/contract.hpp>

namespace opspace::hw2::p1b {

namespace {

// Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p): the tip PD, decoupled, with gravity at the tip
Vector6d tip_pd(const State& s, const Goal& goal) {
  const Eigen::Vector3d F = s.Lambda_v * (-goal.kpx * (s.x - goal.x_d) - goal.kvx * s.dx) + s.p;
  return s.Jv.transpose() * F;
}

// A (-kpj (q - q_d) - kvj dq) + g: the joint task with gravity compensation
Vector6d joint_task(const State& s, const Goal& goal) {
  return s.A * (-goal.kpj * (s.q - goal.q_d) - goal.kvj * s.dq) + s.g;
}

}  // namespace

Vector6d control(Part part, const State& s, const Goal& goal) {
  const Matrix6d I = Matrix6d::Identity();
  switch (part) {
    case Part::kTipPd:
      return tip_pd(s, goal) + s.A * (-goal.kvj * s.dq);

    case Part::kTipPdWithoutJointDamping:
      return tip_pd(s, goal);

    case Part::kPseudoInverseNullspace: {
      // Jv+ = Jv^T (Jv Jv^T)^-1: the tip task is far from singular in this scenario
      const Matrix63d Jv_pinv = s.Jv.transpose() * (s.Jv * s.Jv.transpose()).inverse();
      return tip_pd(s, goal) + (I - s.Jv.transpose() * Jv_pinv.transpose()) * joint_task(s, goal);
    }

    case Part::kDynamicallyConsistentNullspace:
      return tip_pd(s, goal) + (I - s.Jv.transpose() * s.Jbar_v.transpose()) * joint_task(s, goal);
  }
  return Vector6d::Zero();
}

}  // namespace opspace::hw2::p1b
