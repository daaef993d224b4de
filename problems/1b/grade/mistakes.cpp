// Known mistakes of problem 1b. Each wraps the control law it is given (the reference
// solutions, or the grader's oracle) and changes it in one place. Every simulated test checks
// the law at every tick of its runs (law_pin.hpp), so a mistake in a part's law costs each
// simulated test that runs that part, whatever the run's behaviour.
#include "judge/mistakes.hpp"
#include <problems/1b/tests.hpp>

namespace opspace::grading {

namespace p1b_mistakes {  // named: problems share a unity unit (problems/CMakeLists.txt)
namespace {

using hw2::p1b::Goal;
using hw2::p1b::Matrix6d;
using hw2::p1b::Part;
using hw2::p1b::State;
using hw2::p1b::Vector6d;

Matrix6d pseudo_inverse_projector(const State& s) {
  const Eigen::Matrix<double, 6, 3> Jv_pinv = s.Jv.transpose() * (s.Jv * s.Jv.transpose()).inverse();
  return Matrix6d::Identity() - s.Jv.transpose() * Jv_pinv.transpose();
}

Matrix6d consistent_projector(const State& s) { return Matrix6d::Identity() - s.Jv.transpose() * s.Jbar_v.transpose(); }

// The projector of a null-space part (identity for PART1).
Matrix6d projector(Part part, const State& s) {
  if (part == Part::kPseudoInverseNullspace) return pseudo_inverse_projector(s);
  if (part == Part::kDynamicallyConsistentNullspace) return consistent_projector(s);
  return Matrix6d::Identity();
}

bool nullspace_part(Part part) {
  return part == Part::kPseudoInverseNullspace || part == Part::kDynamicallyConsistentNullspace;
}

}  // namespace
}  // namespace p1b_mistakes

std::vector<Mistake> mistakes_1b() {
  using namespace p1b_mistakes;
  namespace id = test_id::p1b;
  return {
      // PART3 then drifts like PART2: the ratio test sees two equal drifts.
      {"PART3 projects with the pseudo-inverse, like PART2",
       "the dynamically consistent projector of PART3 uses Jbar_v: I - Jv^T Jbar_v^T",
       [](Hw2Api& api) {
         api.p1b.control = [law = api.p1b.control](Part part, const State& s, const Goal& g) {
           return law(part == Part::kDynamicallyConsistentNullspace ? Part::kPseudoInverseNullspace : part, s, g);
         };
       },
       {id::kLawPart3, id::kSimPart3, id::kSimDriftRatio}},
      // In PART3 the tip is still held (the projection is dynamically consistent) but joint 2 sags
      // under the gravity left uncompensated in the null space; PART2's law is wrong too, which
      // the ratio test's pin sees.
      {"the null-space task without g",
       "the joint task is A (-kpj (q - q_d) - kvj dq) + g: gravity compensation goes through the projector",
       [](Hw2Api& api) {
         api.p1b.control = [law = api.p1b.control](Part part, const State& s, const Goal& g) {
           const Vector6d tau = law(part, s, g);
           return nullspace_part(part) ? Vector6d(tau - projector(part, s) * s.g) : tau;
         };
       },
       {id::kLawPart2, id::kLawPart3, id::kSimPart3, id::kSimDriftRatio}},
      // A route, not a slip: a drift made to order. PART3's law held 5 cm below x_d drifts ~50 mm
      // RMS from x_d, over ten times PART3's, with joint 2 on q_d: the ratio test's behaviour
      // passes, and only the pin of PART2's law, with the law test, sees that it is not PART2's.
      {"PART2 written as PART3's law aimed 5 cm below x_d",
       "PART2 applies Jv^T F + (I - Jv^T Jv+^T) (A (-kpj (q - q_d) - kvj dq) + g) aimed at x_d: its drift must come "
       "from the pseudo-inverse projector",
       [](Hw2Api& api) {
         api.p1b.control = [law = api.p1b.control](Part part, const State& s, const Goal& g) {
           if (part != Part::kPseudoInverseNullspace) return law(part, s, g);
           Goal off = g;
           off.x_d.z() -= 0.05;
           return law(Part::kDynamicallyConsistentNullspace, s, off);
         };
       },
       {id::kLawPart2, id::kSimDriftRatio}},
      // The unprojected share (I - P) g = Jv^T J_inv^T g compensates gravity at the tip a second
      // time: in PART3 the tip is pushed by p, tens of newtons against a stiffness of kpx Lambda_v,
      // and held centimetres off x_d, so PART3 no longer holds its tip nor drifts ten times less.
      {"g added outside the projector",
       "g belongs to the joint task inside [I - Jv^T J_inv^T] (...); unprojected, it adds Jv^T J_inv^T g at the tip",
       [](Hw2Api& api) {
         api.p1b.control = [law = api.p1b.control](Part part, const State& s, const Goal& g) {
           const Vector6d tau = law(part, s, g);
           return nullspace_part(part) ? Vector6d(tau + (Matrix6d::Identity() - projector(part, s)) * s.g) : tau;
         };
       },
       {id::kLawPart2, id::kLawPart3, id::kSimPart3, id::kSimDriftRatio}},
      {"PART3's projector written as Jv^T Jbar_v^T, without I -",
       "the projector is I - Jv^T Jbar_v^T: the joint task acts in the null space of the tip task",
       [](Hw2Api& api) {
         api.p1b.control = [law = api.p1b.control](Part part, const State& s, const Goal& g) {
           if (part != Part::kDynamicallyConsistentNullspace) return law(part, s, g);
           const Vector6d tip = law(Part::kTipPdWithoutJointDamping, s, g);
           const Vector6d joint = s.A * (-g.kpj * (s.q - g.q_d) - g.kvj * s.dq) + s.g;
           return Vector6d(tip + s.Jv.transpose() * s.Jbar_v.transpose() * joint);
         };
       },
       {id::kLawPart3, id::kSimPart3, id::kSimDriftRatio}},
      // Question ii's lesson: without damping the arm swings freely in the null space (its
      // gravity there is not compensated) and the Coriolis forces of that swing move the tip.
      {"PART1 without the joint damping A (-kvj dq)",
       "PART1 adds A (-kvj dq) to the tip PD",
       [](Hw2Api& api) {
         api.p1b.control = [law = api.p1b.control](Part part, const State& s, const Goal& g) {
           return law(part == Part::kTipPd ? Part::kTipPdWithoutJointDamping : part, s, g);
         };
       },
       {id::kLawPart1, id::kSimPart1}},
      // Without p the tip sags under gravity by |p| / (kpx Lambda_v), centimetres, in every part:
      // PART1 and PART3 miss their bounds and PART3 drifts as much as PART2.
      {"p, the gravity at the tip, left out of the task force",
       "the task force is F = Lambda_v (-kpx (x - x_d) - kvx dx) + p, with p = Jbar_v^T g",
       [](Hw2Api& api) {
         api.p1b.control = [law = api.p1b.control](Part part, const State& s, const Goal& g) {
           return Vector6d(law(part, s, g) - s.Jv.transpose() * s.p);
         };
       },
       {id::kLawPart1, id::kLawWithoutDamping, id::kLawPart2, id::kLawPart3, id::kSimPart1, id::kSimPart3,
        id::kSimDriftRatio}},
  };
}

}  // namespace opspace::grading
