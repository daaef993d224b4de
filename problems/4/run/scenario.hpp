/// @file problems/4/run/scenario.hpp
/// Problem 4: the 3R elbow arm near its singular pose theta = (0, 90 deg, 0) (problem set,
/// shared robots.md), the kinematics of questions i-iv, and question v's closed-loop runs on
/// the simulation, with the student's controller or the plain operational-space controller.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include <problems/4/contract.hpp>
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/model/catalogue.hpp"
#include "opspace/model/model.hpp"
#include "opspace/algorithms/opspace.hpp"
#include "opspace/scenarios/common.hpp"
#include "opspace/scenarios/loop.hpp"
#include "opspace/scenarios/summary.hpp"
#include "opspace/simulation/simulation.hpp"

namespace opspace::scenarios {

namespace p4 {

using hw2::p4::Target;

inline constexpr const char* kRobotFile = catalogue::kRRR.file;
inline constexpr const char* kTipLink = catalogue::kRRR.tip_link;
/// Relative eigenvalue cut-off of the State's robust Lambda_v. A direction whose eigenvalue of
/// Jv A^-1 Jv^T is below 1% of the largest is dropped: the PD force along it would cost
/// torques of order m kpx |x - x_d| / sigma, beyond the 50 N m limits of the arm for a
/// singular value sigma below about a tenth of the largest (guide.md).
inline constexpr double kRobustTolerance = 1e-2;
/// Distance of the target from the start along the singular direction (m).
inline constexpr double kTargetDistance = 0.1;
/// The tip has reached x_d once |x - x_d| stays below this (m).
inline constexpr double kReachTolerance = 5e-3;
/// Simulated seconds of a run.
inline constexpr double kDuration = 3.0;

// The bounds of the graded tests (problems/4/grade/graded.cpp), which hw2-p4 also prints beside its
// results, for question v's controller over a kDuration run.

/// Time until the tip stays within kReachTolerance of x_d (s). The task dynamics
/// xdd = -kpx e - kvx de (kpx = 50, kvx = 20) have poles -10 +- sqrt(50), the slow one at
/// 2.93 /s: 10 cm decay to 5 mm in ln(20) / 2.93 = 1.02 s once the direction is controllable,
/// and the self-motion potential needs a few tenths of a second to leave the lock. 2 s leaves
/// room for both within the kDuration = 3 s run.
inline constexpr double kReachTimeMax = 2.0;
/// The largest joint torque requested (N m): the effort limit of every joint of
/// robots/rrr.urdf, above which the simulation clamps.
inline constexpr double kPeakTorqueMax = 50.0;

/// The tip: the origin of link `end-effector`, the far end of the forearm.
Eigen::Vector3d tip_point();
/// theta = (0, 90 deg, 0): the arm straight up, elbow lock and overhead lock together.
Eigen::Vector3d singular_q();
/// q(0), at rest, with the tip exactly above the base (overhead lock): for kAlongZ0
/// (0, 89 deg, 2 deg), the elbow 2 deg from the elbow lock; for kAlongY0 (0, 80 deg, 20 deg),
/// the elbow bent enough that the target 10 cm along Y0 is within reach (from the stretched
/// arm at the top of the workspace the tip cannot move sideways without coming down).
Eigen::Vector3d initial_q(Target target);
/// The tip's Jv, Jw and position Hessians at q (questions i-iv).
hw2::p4::Kinematics kinematics(const Model& rrr, Data& data, const Eigen::Ref<const Eigen::Vector3d>& q);
/// x_d = x(initial_q(target)) - kTargetDistance Z0 or + kTargetDistance Y0; kpx = kpj = 50, kvx = kvj = 20.
hw2::p4::Goal goal(Target target);

/// Computes the controller's State from (t, q, dq), and the exact task quantities
/// (kTaskInertiaTolerance) of the plain controller. Its workspaces are sized once: it
/// allocates nothing per call (tests/lib/test_tick_noalloc.cpp).
class Observer {
 public:
  /// Workspaces sized for `rrr`, which must outlive the Observer. Throws std::invalid_argument
  /// unless it has 3 joints, std::out_of_range unless it has the tip link.
  explicit Observer(const Model& rrr);
  /// The State at time t at (q, dq), with the robust task quantities (kRobustTolerance).
  const hw2::p4::State& observe(double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                                const Eigen::Ref<const Eigen::VectorXd>& dq);
  /// Lambda, Jbar, N, p of the last observe() with the default (tiny) tolerance.
  const TaskSpace& exact() const { return exact_; }
  const hw2::p4::State& state() const { return state_; }  ///< the last observe()'s State

 private:
  const Model& model_;
  Data data_;
  TaskSpace robust_, exact_;
  Matrix6Xd J0_;
  int tip_frame_;
  hw2::p4::State state_;
};

/// The plain operational-space controller: no self-motion potential, exact Lambda:
///   Gamma = Jv^T (Lambda (-kpx (x - x_d) - kvx dx) + p) + N^T (A (-kvj dq) + g).
Eigen::Vector3d plain_control(const hw2::p4::State& s, const TaskSpace& exact, const hw2::p4::Goal& goal);

/// The control function under test: exercises/ or solutions/ (hw2::p4::control), or a mutant.
using Controller = std::function<Eigen::Vector3d(Target, const hw2::p4::State&, const hw2::p4::Goal&)>;

/// One simulated instant.
struct Sample {
  double t = 0.0;                                 ///< time (s)
  Eigen::Vector3d x = Eigen::Vector3d::Zero();    ///< tip position
  Eigen::Vector3d q = Eigen::Vector3d::Zero();    ///< joint angles (rad)
  Eigen::Vector3d tau = Eigen::Vector3d::Zero();  ///< requested torques
};

/// What a run measured.
struct Summary : RunTotals {  // peak torque, clamped steps, time reached
  double final_error = 0.0;   ///< |x - x_d| at the end (m)
  double reach_time = -1.0;   ///< from when on |x - x_d| <= kReachTolerance (s); -1: never
};

using Result = RunResult<Sample, Summary>;  ///< what a run recorded

/// Runs question v's scenario toward `target` with `control` every 1 ms step.
Result run(Target target, Controller control, const RunOptions& options);

/// A law of question v's run: the State, the exact (not damped) task-space matrices, the Goal.
using Law = std::function<Eigen::Vector3d(const hw2::p4::State&, const TaskSpace&, const hw2::p4::Goal&)>;

/// Question v's scenario for the one closed loop (scenarios/loop.hpp): the 3R arm from
/// initial_q(target) at rest, each tick tau = law(State, exact task quantities, goal(target))
/// checked.
class Scenario {
 public:
  /// Simulated seconds of each graded run and of a --test replay (question v's run).
  static constexpr double kGradedDuration = kDuration;
  using Observer = p4::Observer;
  using Sample = p4::Sample;
  using Summary = p4::Summary;
  static constexpr const char* kRobotFile = p4::kRobotFile;
  static SimulationSettings settings() { return {}; }  ///< the default settings

  /// `who` names the law in errors ("your controller").
  Scenario(Target target, Law law, std::string who);
  void start(Simulation& sim) const;  ///< q(0) = initial_q(target), at rest
  /// The State, the goal with `gains`, tau = law(...) checked.
  Sample tick(Observer& observer, Simulation& sim, const GainOverrides& gains) const;
  std::string what() const;  ///< "problem 4, question v along Z0 (elbow lock), your controller ..."
  static std::vector<std::string> csv_columns();
  std::vector<double> csv_row(const Sample& s) const;  ///< see csv_columns()
  /// Final error, reach time (kReachTolerance), peak torque.
  void summarise(RunResult<Sample, Summary>& result, const Model& rrr, const Simulation& sim) const;
  Target target() const { return target_; }              ///< where the tip goes
  const hw2::p4::Goal& goal() const { return goal_; }    ///< question v's goal for the target

  Law law;          ///< applied from the next tick (the live lab switches it)
  std::string who;  ///< names the law in errors

 private:
  Target target_;
  hw2::p4::Goal goal_;
};

/// Question v's closed loop one tick at a time, shared by run(), run_plain() and the live lab.
using Loop = scenarios::Loop<Scenario>;

/// The same from the same start with plain_control().
Result run_plain(Target target, const RunOptions& options);

/// "along Z0 (elbow lock)" or "along Y0 (overhead lock)", for reports.
std::string describe(Target target);

// What the graded simulated tests (problems/4/grade/graded.cpp) share with the program's replay of
// one of them (--test NAME --seed N): the series their checks read, sample by sample. The grader
// plots them (the report's figures); a replay prints their final values, which match the
// figure's to round-off because both come from these functions applied to the same run.
/// |x - x_d| (m) toward `target`'s x_d.
double tip_error(hw2::p4::Target target, const Sample& s);

}  // namespace p4

}  // namespace opspace::scenarios
