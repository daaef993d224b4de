/// @file problems/1b/run/scenario.hpp
/// Problem 1b: the PUMA 560 holds its tip while joint 2 moves in the null space (numbers
/// from shared robots.md and the problem set), and its closed-loop run on the simulation.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <problems/1b/contract.hpp>
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/model/catalogue.hpp"
#include "opspace/model/model.hpp"
#include "opspace/algorithms/opspace.hpp"
#include "opspace/scenarios/common.hpp"
#include "opspace/scenarios/loop.hpp"
#include "opspace/scenarios/point_task.hpp"
#include "opspace/scenarios/summary.hpp"
#include "opspace/simulation/simulation.hpp"

namespace opspace::scenarios {

namespace p1b {

using hw2::p1b::Vector6d;

inline constexpr const char* kRobotFile = catalogue::kPuma.file;
inline constexpr const char* kTipLink = catalogue::kPuma.tip_link;
inline constexpr double kSettleTime = 2.0;  ///< errors are measured after this (s)
/// Speed bound of the run (rad/s): high enough that PART2's wild wrist motion (a few hundred
/// rad/s) is shown rather than stopped (guide.md).
inline constexpr double kMaxJointSpeed = 1000.0;
/// Simulated seconds of the graded runs and of hw2-p1's default run: one period of q_d(t).
inline constexpr double kDefaultDuration = 10.0;

// The bounds of the graded tests (problems/1b/grade/graded.cpp), which hw2-p1 also prints beside its
// results. Each applies to a Summary of a kDefaultDuration run (errors after kSettleTime).

/// PART1's tip error RMS (m). The tip starts 2.3 mm from x_d; a tip PD with p holds it to the
/// mm scale, while without p (gravity at the tip) it would sag by about |p| / (kpx Lambda),
/// centimetres.
inline constexpr double kPart1TipErrorRmsMax = 5e-3;
/// PART3's largest tip error (m). Dynamically consistent null-space torques cause no tip
/// acceleration, so the tip error stays at PART1's scale: 5 mm.
inline constexpr double kPart3TipErrorMax = 5e-3;
/// PART3's largest q2 tracking error (rad). A joint PD (kpj = 50, kvj = 20) following a sine of
/// amplitude pi/8 at w = 2 pi / 10 lags with error amplitude
/// (pi/8) |(-w^2 + j kvj w) / (kpj - w^2 + j kvj w)| = 0.096 rad (closed form of the
/// second-order response); 0.15 rad leaves room for the coupling.
inline constexpr double kPart3Q2ErrorMax = 0.15;
/// PART2's largest q2 tracking error (rad). PART2 is still the null-space law: its joint task
/// keeps joint 2 near q_d (amplitude pi/8 = 0.39 rad) even while the tip drifts, whereas an arm
/// left without control falls towards its hanging pose, more than 1 rad from q_d.
inline constexpr double kPart2Q2ErrorMax = 0.5;
/// The smallest ratio of PART2's tip error RMS to PART3's. With J+ the null-space torque leaves
/// Jv^T (Jbar_v - Jv+)^T g (plus the projected joint task) on the tip, tens of newtons at these
/// poses, while PART3 leaves none: PART2 drifts at least ten times more.
inline constexpr double kPart2OverPart3TipErrorRmsMin = 10.0;

/// The tip: point (-0.2, 0, 0) of link `end-effector`.
Eigen::Vector3d tip_point();
/// q(0) = (90, -22.5, 180, 90, 100, 180) deg, at rest.
Vector6d initial_q();
/// q_d[1](t) = -pi/8 + pi/8 sin(2 pi t / 10).
double desired_q2(double t);
/// x_d = (-0.15, 0.81, 0.58); q_d = q except q_d[1] = desired_q2(t); kpx = kpj = 50, kvx = kvj = 20.
hw2::p1b::Goal goal(double t, const Eigen::Ref<const Vector6d>& q);

/// Computes the controller's State from (t, q, dq): tip kinematics, A, g and the
/// operational-space matrices of the tip task (scenarios/point_task.hpp). Allocates nothing per call.
class Observer : public PointTaskObserver<hw2::p1b::State> {
 public:
  /// Workspaces sized for `puma`, which must outlive the Observer. Throws std::invalid_argument
  /// unless it has 6 joints, std::out_of_range unless it has the tip link.
  explicit Observer(const Model& puma);
};

/// The control function under test: exercises/ or solutions/ (hw2::p1b::control), or a mutant.
using Controller = std::function<Vector6d(hw2::p1b::Part, const hw2::p1b::State&, const hw2::p1b::Goal&)>;

/// One simulated instant.
struct Sample {
  double t = 0.0;                               ///< time (s)
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  ///< tip position
  Vector6d q = Vector6d::Zero();                ///< joint positions (rad)
  double q2_desired = 0.0;                      ///< q2_d, the null-space goal of joint 2 (rad)
  Vector6d tau = Vector6d::Zero();              ///< torques requested by the controller (N m)
};

/// What a run measured; errors are taken after kSettleTime.
struct Summary : RunTotals {
  double tip_error_max = 0.0;  ///< max |x - x_d| (m)
  double tip_error_rms = 0.0;  ///< RMS |x - x_d| (m)
  double q2_error_max = 0.0;   ///< max |q2 - q2_d| (rad)
  double q2_error_rms = 0.0;   ///< RMS |q2 - q2_d| (rad)
};

using Result = RunResult<Sample, Summary>;  ///< what a run recorded

/// Problem 1b's scenario for the one closed loop (scenarios/loop.hpp): the PUMA from q(0) at
/// rest, each tick tau = control(part, State, goal(t, q)), its torques checked.
class Scenario {
 public:
  /// Simulated seconds of each graded run and of a --test replay (one period of q_d).
  static constexpr double kGradedDuration = kDefaultDuration;
  using Observer = p1b::Observer;
  using Sample = p1b::Sample;
  using Summary = p1b::Summary;
  static constexpr const char* kRobotFile = p1b::kRobotFile;
  /// Speeds up to kMaxJointSpeed: PART2's wild wrist is the lesson, not a stop.
  static SimulationSettings settings();

  /// `control` applies law `part`.
  Scenario(hw2::p1b::Part part, Controller control);
  void start(Simulation& sim) const;  ///< q(0) = initial_q(), at rest
  /// State, goal(t, q) with `gains`, tau = control(part, ...) checked (ControllerError names part).
  Sample tick(Observer& observer, Simulation& sim, const GainOverrides& gains);
  std::string what() const;  ///< "problem 1b, PART3: ..."
  static std::vector<std::string> csv_columns();
  std::vector<double> csv_row(const Sample& s) const;  ///< see csv_columns(); x_d the fixed target
  /// Errors after kSettleTime against x_d, peak torque.
  void summarise(RunResult<Sample, Summary>& result, const Model& model, const Simulation& sim) const;
  const Eigen::Vector3d& x_d() const { return x_d_; }  ///< the tip's fixed target

  hw2::p1b::Part part;  ///< the law control() applies from the next tick (the live lab switches it)

 private:
  Controller control_;
  Eigen::Vector3d x_d_;
  hw2::p1b::Part named_part_;  // the part `who_` names ("your PART3 controller")
  std::string who_;
};

/// Problem 1b's closed loop one tick at a time, shared by run() and the live lab.
using Loop = scenarios::Loop<Scenario>;

/// Runs problem 1b's scenario with `control` applying law `part` every 1 ms step.
Result run(hw2::p1b::Part part, Controller control, const RunOptions& options);

/// "PART1: tip PD with joint damping" and so on, for reports.
std::string describe(hw2::p1b::Part part);

// What the graded simulated tests (problems/1b/grade/graded.cpp) share with the program's replay of
// one of them (--test NAME --seed N): the series their checks read, sample by sample. The grader
// plots them (the report's figures); a replay prints their final values, which match the
// figure's to round-off because both come from these functions applied to the same run.
double tip_error(const Sample& s);  ///< |x - x_d| (m), x_d the scenario's fixed target
double q2_error(const Sample& s);   ///< |q2 - q2_d| (rad)

}  // namespace p1b

}  // namespace opspace::scenarios
