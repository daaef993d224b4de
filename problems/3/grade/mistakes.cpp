// Known mistakes of problem 3. The law is written out with one mistake made. Every simulated
// test pins the law at every tick of the run (law_pin.hpp): a mistake whose torque is not the
// law's costs each behaviour test whose judged statistic it moves (the scenario's probes in the
// force directions, p3::kProbeAmplitude and p3::kProbeTilt, make each different law move one);
// one that leaves the run's torque the law's (F_d without Omega-bar, with the run's F_d along x)
// costs the law test alone. Its rubric (guide.md) lists the points each costs.
#include "opspace/algorithms/euler_params.hpp"
#include <problems/3/contract.hpp>

#include "judge/mistakes.hpp"
#include <problems/3/tests.hpp>
#include "answers.hpp"
#include "judge/oracles.hpp"

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
  bool no_selection = false;      // problem 2's law plus F_d: neither Omega nor Omega-bar
  bool moments_in_motion = false;  // Omega also keeps M_y and M_z (Omega-bar F_x alone)
  bool damping_everywhere = false;  // - kvx ([v; w] - E^+ xdot_d) outside Omega: every direction
  bool force_damping = false;      // + Lambda0 Omega-bar (-kvx [v; w]): damping in the force directions
  bool reversed_orientation = false;  // delta_phi = E_r^+ (lambda_d - lambda)
};

// Omega of each law: the problem set's, or with the moments about y and z motion-controlled.
Matrix6d motion_omega(const Mistakes& m) {
  if (m.swapped) return oracle::omega_bar();
  if (m.no_selection) return Matrix6d::Identity();
  Matrix6d omega = oracle::omega();
  if (m.moments_in_motion) omega(4, 4) = omega(5, 5) = 1.0;
  return omega;
}
Matrix6d force_omega(const Mistakes& m) {
  if (m.swapped) return oracle::omega();
  if (m.no_selection) return Matrix6d::Identity();
  Matrix6d omega_bar = oracle::omega_bar();
  if (m.moments_in_motion) omega_bar(4, 4) = omega_bar(5, 5) = 0.0;
  return omega_bar;
}
Matrix6d moments_in_motion() { return motion_omega(Mistakes{false, false, false, false, true}); }
Matrix6d only_force_x() { return force_omega(Mistakes{false, false, false, false, true}); }

Vector7d law(const State& s, const Goal& goal, const Mistakes& m) {
  const Matrix67d E_pinv = representation_matrix_pinv(s.lambda);
  Vector6d error, twist;
  error << s.x_p - goal.x_d.head<3>(), orientation_error(s.lambda, goal.x_d.tail<4>());
  if (m.reversed_orientation) error.tail<3>() = -error.tail<3>();
  twist << s.v, s.w;
  const Vector6d damping = -goal.kvx * (twist - E_pinv * goal.xdot_d);
  const Vector6d motion = -goal.kpx * error + (m.damping_everywhere ? Vector6d::Zero() : damping) + E_pinv * goal.xddot_d;
  const Matrix6d omega = motion_omega(m);
  const Matrix6d omega_bar = force_omega(m);
  Vector6d force = m.no_omega_bar ? goal.F_d : Vector6d(omega_bar * goal.F_d);
  if (m.force_times_lambda) force = s.Lambda0 * force;
  Vector6d F = s.Lambda0 * omega * motion + s.p + force;
  if (m.damping_everywhere) F += s.Lambda0 * damping;
  if (m.force_damping) F += s.Lambda0 * (oracle::omega_bar() * (-goal.kvx * twist));
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
      // x becomes motion-controlled to the probe's x_d, which moves 5 cm through the plane, and
      // y, z and the rotation about x get only the feed-forward "force" 0: the tool tilts, leaves
      // the plane and drifts; every statistic moves.
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
      // turns with lambda_d: those three tests judge what the law puts there, and pay.
      {"the desired force multiplied by Lambda0 (treated as an acceleration)",
       "F_d is a force: Omega-bar F_d is added after Lambda0, not multiplied by it",
       [](Hw2Api& api) { api.p3.control = &with<&Mistakes::force_times_lambda>; },
       {id::kLaw, id::kSimForce, id::kSimPosition}},
      // Problem 2's law plus F_d: x is motion-controlled too, to the scenario's x_d, which moves
      // 5 cm through the plane (p3::kProbeAmplitude): the push swings by about 9.5 N (5.5 N mean
      // error), and M_y, M_z servo the tilted lambda_d (p3::kProbeTilt): 3 deg of tilt, 7.8 mm
      // of y-z error. The rotation about x and the contact stay the law's.
      {"Omega and Omega-bar left out (problem 2's law plus F_d)",
       "Omega filters the motion command and Omega-bar the force: Lambda0 Omega (...) + p + Omega-bar F_d",
       [](Hw2Api& api) {
         api.p3.motion_selection = [] { return Matrix6d::Identity().eval(); };
         api.p3.force_selection = [] { return Matrix6d::Identity().eval(); };
         api.p3.control = &with<&Mistakes::no_selection>;
       },
       {id::kSelection, id::kLaw, id::kSimForce, id::kSimFlat, id::kSimPosition}},
      // M_y and M_z servo lambda_d's 5-degree tilt (p3::kProbeTilt); the plane holds the face
      // flat, but Lambda0 couples those moments into F_y: 5.8 mm of y-z error.
      {"the moments about y and z motion-controlled (Omega keeps M_y and M_z)",
       "M_y and M_z are force-controlled: Omega keeps F_y, F_z and M_x only, Omega-bar F_x, M_y and M_z",
       [](Hw2Api& api) {
         api.p3.motion_selection = &moments_in_motion;
         api.p3.force_selection = &only_force_x;
         api.p3.control = &with<&Mistakes::moments_in_motion>;
       },
       {id::kSelection, id::kLaw, id::kSimPosition}},
      // -kvx (v_x - xdot_d) along x: the scenario's xdot_d along x (5 cm at w = 2 pi / 5) adds
      // a 4.3 N swing to the push (p3::kProbeAmplitude): 2.7 N mean error, and 3.3 mm of y-z.
      {"the task damping applied in every direction, outside Omega",
       "the damping -kvx ([v; w] - E^+ xdot_d) is part of the motion command, inside Lambda0 Omega (...)",
       [](Hw2Api& api) { api.p3.control = &with<&Mistakes::damping_everywhere>; },
       {id::kLaw, id::kSimForce, id::kSimPosition}},
      // A later year's law: damping of the force directions' velocity. In contact the plane
      // holds v_x, w_y and w_z at zero, so the run judges as the reference's: the law test alone.
      {"damping added in the force directions (+ Lambda0 Omega-bar (-kvx [v; w]))",
       "the force directions get the feed-forward force alone: + p + Omega-bar F_d, no damping",
       [](Hw2Api& api) { api.p3.control = &with<&Mistakes::force_damping>; },
       {id::kLaw}},
      // Problem 2's sign slip: the rotation about x is pushed away from lambda_d.
      {"delta_phi with the wrong sign, E^+ (lambda_d - lambda)",
       "delta_phi = E_r^+ (lambda - lambda_d): the PD pulls lambda towards lambda_d",
       [](Hw2Api& api) { api.p3.control = &with<&Mistakes::reversed_orientation>; },
       {id::kLaw, id::kSimRotation}},
  };
}

}  // namespace opspace::grading
