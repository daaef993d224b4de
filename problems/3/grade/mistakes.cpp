// Known mistakes of problem 3. The law is written out with one mistake made. Every simulated
// test pins the law at every tick of the run (law_pin.hpp): a mistake that makes the run's
// torque a different law costs all five of them, whatever the run's behaviour; one that leaves
// the run's torque the law's (F_d without Omega-bar, with the run's F_d along x) costs the law
// test alone. its rubric (guide.md) lists the points each costs.
#include <opspace/algorithms/euler_params.hpp>
#include <problems/3/contract.hpp>

#include "mistakes.hpp"
#include "problems/3/tests.hpp"
#include "answers.hpp"
#include "oracles.hpp"

namespace opspace::grading {

namespace p3_mistakes {  // named: problems share a unity unit (problems/CMakeLists.txt)
namespace {

using hw2::p3::Goal;
using hw2::p3::Matrix6d;
using hw2::p3::State;
using hw2::p3::Vector6d;
using hw2::p3::Vector7d;

// What each mutant gets wrong in the law.
struct Mistakes {
  bool swapped = false;           // Omega and Omega-bar exchanged
  bool no_omega_bar = false;      // + F_d instead of + Omega-bar F_d
  bool force_times_lambda = false;  // + Lambda0 Omega-bar F_d
};

Vector7d law(const State& s, const Goal& goal, const Mistakes& m) {
  const Matrix67d E_pinv = representation_matrix_pinv(s.lambda);
  Vector6d error, twist;
  error << s.x_p - goal.x_d.head<3>(), orientation_error(s.lambda, goal.x_d.tail<4>());
  twist << s.v, s.w;
  const Vector6d motion = -goal.kpx * error - goal.kvx * (twist - E_pinv * goal.xdot_d) + E_pinv * goal.xddot_d;
  const Matrix6d omega = m.swapped ? oracle::omega_bar() : oracle::omega();
  const Matrix6d omega_bar = m.swapped ? oracle::omega() : oracle::omega_bar();
  Vector6d force = m.no_omega_bar ? goal.F_d : Vector6d(omega_bar * goal.F_d);
  if (m.force_times_lambda) force = s.Lambda0 * force;
  const Vector6d F = s.Lambda0 * omega * motion + s.p + force;
  return s.J0.transpose() * F + s.N0.transpose() * (s.A * (-goal.kvj * s.dq) + s.g);
}

// The law with one mistake made: &with<&Mistakes::swapped> and so on.
template <bool Mistakes::*kMistake>
Vector7d with(const State& s, const Goal& goal) {
  Mistakes m;
  m.*kMistake = true;
  return law(s, goal, m);
}

}  // namespace
}  // namespace p3_mistakes

std::vector<Mistake> mistakes_3() {
  using namespace p3_mistakes;
  namespace id = test_id::p3;
  return {
      // x becomes motion-controlled to x_d = 0, where the face rests on the plane (p3's start):
      // it touches but never pushes, so every contact test fails, the flat one included ("the
      // tool never pushed on the plane"; its rotations about y and z are motion-controlled to
      // lambda_d, which keeps the face parallel to the plane all the same). y, z and the
      // rotation about x get only the feed-forward "force" 0 and drift by 0.14 m and 1.5 rad RMS.
      {"Omega and Omega-bar swapped (motion control along x and about y, z; force in the rest)",
       "Omega keeps the motion directions F_y, F_z, M_x; Omega-bar the force directions F_x, M_y, M_z",
       [](Hw2Api& api) {
         api.p3.motion_selection = &oracle::omega_bar;
         api.p3.force_selection = &oracle::omega;
         api.p3.control = &with<&Mistakes::swapped>;
       },
       {id::kSelection, id::kLaw, id::kSimForce, id::kSimFlat, id::kSimPosition, id::kSimRotation,
        id::kSimContact}},
      // The scenario's F_d = [10, 0, 0, 0, 0, 0] lies in the force directions already, so
      // without Omega-bar the torque is the same in simulation, at every tick (the pin passes):
      // only the law test, whose F_d has components in the motion directions too, sees it.
      {"the desired force F_d added without Omega-bar",
       "the force goes through Omega-bar: + Omega-bar F_d, so that it acts only in the force directions",
       [](Hw2Api& api) { api.p3.control = &with<&Mistakes::no_omega_bar>; },
       {id::kLaw}},
      // Lambda0 F_d = 10 Lambda0(:, 0): at the start Lambda0(0, 0) = 3.4 kg, so the tool pushes
      // 33 N on average instead of 10 N; Lambda0(1, 0) = 1.1 kg adds an 11 N push along y that
      // the motion loop must fight, 33 mm RMS of y, z error. The face stays flat, in contact, and
      // turns with lambda_d: those three tests fail on the pin of the law alone.
      {"the desired force multiplied by Lambda0 (treated as an acceleration)",
       "F_d is a force: Omega-bar F_d is added after Lambda0, not multiplied by it",
       [](Hw2Api& api) { api.p3.control = &with<&Mistakes::force_times_lambda>; },
       {id::kLaw, id::kSimForce, id::kSimFlat, id::kSimPosition, id::kSimRotation, id::kSimContact}},
  };
}

}  // namespace opspace::grading
