// A 1b controller that tells its runner processes apart by what each has answered before (issue
// 58): the reference's law where its trick says "a process that makes one run alone", zero torque
// elsewhere. FAULT is the trick:
//   first  the reference only in a process whose first call was PART3 at t = 0, as a second
//          runner's was when it made PART3's run ahead (scored 4 with --jobs 2, 0 with one runner);
//   count  the reference while its process has answered at most 15 000 calls: a run is 10 s of
//          1 ms ticks, about 10 000 calls, so past 15 000 a process has answered another run.
// Whoever makes the runs, the grade must be the same (check_same_grade.sh).
#include <problems/1b/contract.hpp>

#include <string>

namespace opspace::hw2::p1b {

namespace {

// The reference's laws (solutions/p1b.cpp).
Vector6d tip_pd(const State& s, const Goal& goal) {
  const Eigen::Vector3d F = s.Lambda_v * (-goal.kpx * (s.x - goal.x_d) - goal.kvx * s.dx) + s.p;
  return s.Jv.transpose() * F;
}

Vector6d joint_task(const State& s, const Goal& goal) {
  return s.A * (-goal.kpj * (s.q - goal.q_d) - goal.kvj * s.dq) + s.g;
}

Vector6d law(Part part, const State& s, const Goal& goal) {
  const Matrix6d I = Matrix6d::Identity();
  switch (part) {
    case Part::kTipPd:
      return tip_pd(s, goal) + s.A * (-goal.kvj * s.dq);
    case Part::kTipPdWithoutJointDamping:
      return tip_pd(s, goal);
    case Part::kPseudoInverseNullspace: {
      const Matrix63d Jv_pinv = s.Jv.transpose() * (s.Jv * s.Jv.transpose()).inverse();
      return tip_pd(s, goal) + (I - s.Jv.transpose() * Jv_pinv.transpose()) * joint_task(s, goal);
    }
    case Part::kDynamicallyConsistentNullspace:
      return tip_pd(s, goal) + (I - s.Jv.transpose() * s.Jbar_v.transpose()) * joint_task(s, goal);
  }
  return Vector6d::Zero();
}

}  // namespace

Vector6d control(Part part, const State& s, const Goal& goal) {
  static long calls = 0;               // this process's calls so far
  static bool first_part3_at_0 = false;  // its first call was PART3 at t = 0
  if (calls++ == 0) first_part3_at_0 = part == Part::kDynamicallyConsistentNullspace && s.t == 0.0;
  const std::string trick = "@FAULT@";
  const bool honest = trick == "first" ? first_part3_at_0 : calls <= 15000;
  return honest ? law(part, s, goal) : Vector6d::Zero();
}

}  // namespace opspace::hw2::p1b
