// Known-wrong controllers of problem 1b. Each changes the reference law in one place.
#include <opspace/hw2/p1b.hpp>

#include "mutants.hpp"

namespace opspace::mutants {

namespace {

using hw2::p1b::Goal;
using hw2::p1b::Matrix6d;
using hw2::p1b::Part;
using hw2::p1b::State;
using hw2::p1b::Vector6d;

// PART3 written with the pseudo-inverse projector, as in PART2.
Vector6d part3_with_pseudo_inverse(Part part, const State& s, const Goal& goal) {
  return hw2::p1b::control(part == Part::kDynamicallyConsistentNullspace ? Part::kPseudoInverseNullspace : part,
                           s, goal);
}

// The projector applied to A (-kpj (q - q_d) - kvj dq) alone: g left out of the null-space task.
Vector6d nullspace_task_without_gravity(Part part, const State& s, const Goal& goal) {
  const Matrix6d I = Matrix6d::Identity();
  switch (part) {
    case Part::kPseudoInverseNullspace: {
      const Eigen::Matrix<double, 6, 3> Jv_pinv = s.Jv.transpose() * (s.Jv * s.Jv.transpose()).inverse();
      return hw2::p1b::control(part, s, goal) - (I - s.Jv.transpose() * Jv_pinv.transpose()) * s.g;
    }
    case Part::kDynamicallyConsistentNullspace:
      return hw2::p1b::control(part, s, goal) - (I - s.Jv.transpose() * s.Jbar_v.transpose()) * s.g;
    default:
      return hw2::p1b::control(part, s, goal);
  }
}

// PART3's projector written as Jv^T Jbar_v^T: the "I -" forgotten, so the joint task is sent
// into the task space instead of its null space.
Vector6d projector_without_identity(Part part, const State& s, const Goal& goal) {
  if (part != Part::kDynamicallyConsistentNullspace) return hw2::p1b::control(part, s, goal);
  const Vector6d tip = hw2::p1b::control(Part::kTipPdWithoutJointDamping, s, goal);
  const Vector6d joint = s.A * (-goal.kpj * (s.q - goal.q_d) - goal.kvj * s.dq) + s.g;
  return tip + s.Jv.transpose() * s.Jbar_v.transpose() * joint;
}

// PART1 without the joint damping A (-kvj dq).
Vector6d part1_without_damping(Part part, const State& s, const Goal& goal) {
  return hw2::p1b::control(part == Part::kTipPd ? Part::kTipPdWithoutJointDamping : part, s, goal);
}

}  // namespace

std::vector<Mutant> p1b_mutants() {
  const std::string law1 = "ii. PART1 applies Jv^T (Lambda_v (-kpx (x - x_d) - kvx dx) + p) + A (-kvj dq)";
  const std::string sim1 = "ii. in simulation PART1 brings the tip to x_d and holds it";
  const std::string law2 = "iii. PART2 projects the joint task with I - Jv^T Jv+^T";
  const std::string law3 = "iv. PART3 projects the joint task with I - Jv^T Jbar_v^T";
  const std::string sim3 = "iv. in simulation PART3 holds the tip within 5 mm while q2 follows q_d";
  const std::string ratio = "iii. in simulation the PART2 tip drifts at least ten times more than PART3's";
  return {
      // PART3 then drifts like PART2: the ratio test sees two equal drifts.
      {"PART3 with the pseudo-inverse projector",
       [](grading::Hw2Api& api) { api.p1b.control = &part3_with_pseudo_inverse; },
       {law3, sim3, ratio}},
      // The tip is still held (the projection is dynamically consistent) but joint 2 sags under
      // the gravity left uncompensated in the null space.
      {"null-space task without g",
       [](grading::Hw2Api& api) { api.p1b.control = &nullspace_task_without_gravity; },
       {law2, law3, sim3}},
      {"PART3 projector written as Jv^T Jbar_v^T, without I -",
       [](grading::Hw2Api& api) { api.p1b.control = &projector_without_identity; },
       {law3, sim3, ratio}},
      // Question ii's lesson: without damping the arm swings freely in the null space (its
      // gravity there is not compensated) and the Coriolis forces of that swing move the tip.
      {"PART1 without joint damping",
       [](grading::Hw2Api& api) { api.p1b.control = &part1_without_damping; },
       {law1, sim1}},
  };
}

}  // namespace opspace::mutants
