// A known-wrong problem 1b (the catalogue's "PART3 projects with the pseudo-inverse, like
// PART2", problems/1b/grade/mistakes.cpp) as a student would write it: solutions/p1b.cpp with
// PART3's projector I - Jv^T Jv+^T. Graded as a submission and linked into hw2-p1 as a program
// (hw2-p1-part3-pinv), by check_report_page.sh: the report's page plots its drift against the
// reference, and its replay command, run on this program, reproduces the graded run.
#include <problems/1b/contract.hpp>

namespace opspace::hw2::p1b {

namespace {

// Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p)
Vector6d tip_pd(const State& s, const Goal& goal) {
  const Eigen::Vector3d F = s.Lambda_v * (-goal.kpx * (s.x - goal.x_d) - goal.kvx * s.dx) + s.p;
  return s.Jv.transpose() * F;
}

// A (-kpj (q - q_d) - kvj dq) + g
Vector6d joint_task(const State& s, const Goal& goal) {
  return s.A * (-goal.kpj * (s.q - goal.q_d) - goal.kvj * s.dq) + s.g;
}

// tip_pd + (I - Jv^T Jv+^T) joint_task, Jv+ = Jv^T (Jv Jv^T)^-1
Vector6d with_pseudo_inverse(const State& s, const Goal& goal) {
  const Matrix63d Jv_pinv = s.Jv.transpose() * (s.Jv * s.Jv.transpose()).inverse();
  return tip_pd(s, goal) + (Matrix6d::Identity() - s.Jv.transpose() * Jv_pinv.transpose()) * joint_task(s, goal);
}

}  // namespace

Vector6d control(Part part, const State& s, const Goal& goal) {
  switch (part) {
    case Part::kTipPd: return tip_pd(s, goal) + s.A * (-goal.kvj * s.dq);
    case Part::kTipPdWithoutJointDamping: return tip_pd(s, goal);
    case Part::kPseudoInverseNullspace: return with_pseudo_inverse(s, goal);
    case Part::kDynamicallyConsistentNullspace: return with_pseudo_inverse(s, goal);  // the mistake
  }
  return Vector6d::Zero();
}

}  // namespace opspace::hw2::p1b
