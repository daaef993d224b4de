/// @file simulation/simulation.hpp
/// A physics simulation of a Model on Bullet's btMultiBody (Featherstone), double precision.
///
/// The same Model (one URDF) builds the controller's dynamics and this simulation, so the two
/// agree to rounding: tests/lib/test_simulation*.cpp check Bullet's accelerations and mass
/// matrix against dynamics.hpp. The robot has a fixed base at the world origin; the world frame
/// is the Model's base frame.
///
/// Behaviour, fixed and documented (docs/simulation.md):
/// - one step() advances exactly dt (default 1 ms); torques are applied for that step only;
/// - RK4 integration by default (energy-conserving enough for 5 s runs), Euler on request;
/// - no link damping, no sleeping, no silent velocity clamp, no self collision, joint position
///   limits are not enforced;
/// - a joint's armature (Body::armature, the motor's reflected inertia), which Bullet's multibody
///   has no term for, is applied as a joint-space correction: each step gives Bullet the torque
///   tau - armature_i qdd_i, with qdd from opspace's dynamics with the armature over the step
///   (at its start for Euler, exact; the RK4 average of its stages for RK4), so that Bullet's
///   acceleration is the armed robot's; contact impulses see the robot without armature;
/// - a torque beyond a joint's URDF effort limit is clamped to the limit and counted
///   (SimulationSummary::clamped_steps); an effort limit <= 0 means "no limit";
/// - a state that is not finite, or a joint speed beyond SimulationSettings::max_joint_speed,
///   throws SimulationError naming the joint and the time; the simulation then refuses to step.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "opspace/model/model.hpp"

class btMultiBody;
class btMultiBodyDynamicsWorld;

namespace opspace {

/// A run that went wrong: a non-finite state or a joint speed beyond the bound.
class SimulationError : public std::runtime_error {
 public:
  /// `message` for what(); the offending `joint` (or empty) and the simulated `time` (s).
  SimulationError(const std::string& message, std::string joint, double time)
      : std::runtime_error(message), joint_(std::move(joint)), time_(time) {}
  /// Name of the offending joint (empty if the fault is not tied to one joint).
  const std::string& joint() const { return joint_; }
  /// Simulated time (s) at the end of the failed step.
  double time() const { return time_; }

 private:
  std::string joint_;
  double time_;
};

enum class Integrator { kRK4, kEuler };

/// How a Simulation steps: time step, integrator, speed bound, contact solver.
struct SimulationSettings {
  double dt = 1e-3;                      ///< step (s)
  Integrator integrator = Integrator::kRK4;  ///< Bullet's multibody integration scheme
  /// A step that ends with |qdot_i| above this (rad/s or m/s) throws SimulationError. No arm of
  /// the problems moves this fast: a PUMA falling freely for 20 s whips its light last link to
  /// 159 rad/s from problem 1b's start, 187 rad/s from q = 0 and 55-343 rad/s from ten random
  /// starts (measured, RK4 at 1 ms), and problem 1b's PART2 spins the wrist at a few hundred.
  /// Bullet's own silent clamp is pushed far above it.
  double max_joint_speed = 1000.0;
  int solver_iterations = 50;            ///< contact solver iterations per step
};

/// Surface properties of a static obstacle. Link colliders have friction 1 and restitution 1,
/// and Bullet multiplies the two sides, so the obstacle's values are the contact's values.
struct Material {
  double friction = 0.5;     ///< Coulomb coefficient
  double restitution = 0.0;  ///< 0: plastic impact, 1: elastic
};

/// One contact point between a robot body and an obstacle, after the last step.
struct Contact {
  int body = -1;                       ///< index in Model::bodies
  int obstacle = -1;                   ///< id returned by add_plane / add_box
  Eigen::Vector3d position_on_body;    ///< world frame (m)
  Eigen::Vector3d position_on_obstacle;  ///< world frame (m)
  Eigen::Vector3d normal;              ///< world, unit, pointing from the obstacle to the body
  double distance = 0.0;               ///< signed gap (m), negative when penetrating
  Eigen::Vector3d force;               ///< on the body, world frame (N): normal + friction
};

/// Contact force and moment on one body, world frame; the moment is about the body frame
/// origin (the URDF link frame of Model::bodies[i]).
struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< sum of the contact forces (N)
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  ///< their moment about the body frame origin (N m)
};

/// What a run did, for the caller's report.
struct SimulationSummary {
  long steps = 0;     ///< steps taken
  double time = 0.0;  ///< simulated time reached, steps * dt (s)
  std::vector<long> clamped_steps;  ///< per joint: steps whose requested torque was clamped
  std::vector<double> max_requested_torque;  ///< per joint: max |tau| requested (N m or N)
  /// Sum of clamped_steps over the joints.
  long total_clamped() const;
};

/// Energies of the simulated robot, from Bullet's own state.
struct Energy {
  double kinetic = 0.0;    ///< J
  double potential = 0.0;  ///< J, zero at the base origin height: -sum m_i g . c_i
  double total() const { return kinetic + potential; }  ///< kinetic + potential (J)
};

/// A Bullet multibody world built from a Model. Owns every Bullet object; not copyable.
class Simulation {
 public:
  /// Builds the world: one multibody from `model` (fixed base at the origin, link colliders
  /// from model.collisions), gravity model.gravity, at q = qdot = 0, t = 0.
  explicit Simulation(const Model& model, const SimulationSettings& settings = {});
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Adds the static half-space {x : normal . x <= offset}; returns its obstacle id.
  int add_plane(const Eigen::Vector3d& normal, double offset, const Material& material = {});
  /// Adds a static box of full edge lengths `size` at `pose`; returns its obstacle id.
  int add_box(const Eigen::Vector3d& size, const Eigen::Isometry3d& pose,
              const Material& material = {});

  /// Sets the joint positions and velocities (and refreshes link poses and colliders).
  void set_state(const Eigen::Ref<const Eigen::VectorXd>& q,
                 const Eigen::Ref<const Eigen::VectorXd>& qdot);
  /// Joint positions (dof).
  const Eigen::VectorXd& q() const;
  /// Joint velocities (dof).
  const Eigen::VectorXd& qdot() const;
  /// Simulated time (s) since construction.
  double time() const;

  /// Advances exactly one dt with joint torques `tau` (clamped to the effort limits) plus
  /// gravity and contacts. Throws std::invalid_argument for a wrong size or a non-finite
  /// torque, SimulationError if the new state is not finite or too fast.
  void step(const Eigen::Ref<const Eigen::VectorXd>& tau);

  /// Adds an external force `force` (world frame, N) at the world point `point` on body `body`
  /// for the next step() only, as Bullet's link force at the body's centre of mass plus the
  /// torque (point - com) x force: a push from outside the robot, never a joint torque (the
  /// effort limits and their count stay the controller's). Several calls before a step add up.
  /// Throws std::out_of_range for a bad body, std::invalid_argument for a non-finite value.
  void push(int body, const Eigen::Vector3d& force, const Eigen::Vector3d& point);

  /// Pose in the world of body i's frame (the URDF link frame).
  Eigen::Isometry3d body_pose(int body) const;
  /// Pose in the world of any URDF link, moving or merged; throws std::out_of_range naming it.
  Eigen::Isometry3d link_pose(const std::string& link) const;
  /// Index in Model::bodies of the body that carries link `link` (-1: the fixed base).
  int link_body(const std::string& link) const;

  /// Contact points after the last step.
  const std::vector<Contact>& contacts() const;
  /// Contact force and moment on body i after the last step (zero if it touches nothing).
  const Wrench& contact_wrench(int body) const;
  /// The same for the body that carries link `link`.
  const Wrench& contact_wrench(const std::string& link) const;

  /// Kinetic and potential energy, from Bullet's link velocities and poses (the kinetic energy
  /// includes the rotors' 1/2 armature_i qdot_i^2).
  Energy energy() const;

  /// Bullet's inverse mass matrix M^-1(q) at the current state, column by column from its
  /// articulated-body routines (for cross-checks; allocates nothing after the first call).
  /// It is Bullet's own: without the joints' armature.
  void inverse_mass_matrix(Eigen::Ref<Eigen::MatrixXd> Minv);

  const SimulationSummary& summary() const;    ///< steps, time, clamped torques so far
  const SimulationSettings& settings() const;  ///< as given to the constructor
  const Model& model() const;                  ///< the Model the world was built from

  /// The Bullet objects, for what this class does not wrap. Changing them voids the promises
  /// above.
  btMultiBody& multibody();
  btMultiBodyDynamicsWorld& world();  ///< the Bullet world (see multibody())

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace opspace
