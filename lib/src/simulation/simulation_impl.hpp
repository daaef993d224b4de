// The state of a Simulation (simulation.hpp) and its Bullet world, private to lib/src/simulation:
// build.cpp builds the world from a Model, step.cpp steps it and reads the contacts,
// simulation.cpp is the public class. See docs/simulation.md.

#pragma once

#include "opspace/simulation/simulation.hpp"

#include <btBulletDynamicsCommon.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "../math/small_decompositions.hpp"
#include "opspace/algorithms/kinematics.hpp"

static_assert(sizeof(btScalar) == 8,
              "Bullet must be the double-precision build (bullet-float64, BT_USE_DOUBLE_PRECISION)");

namespace opspace {

// Conversions between Eigen and Bullet, and the principal inertial frame of a body.
namespace bullet {

inline btVector3 to_bt(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }
inline Eigen::Vector3d to_eigen(const btVector3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }

inline btMatrix3x3 to_bt_matrix(const Eigen::Matrix3d& R) {
  return btMatrix3x3(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2));
}
inline Eigen::Matrix3d to_eigen(const btMatrix3x3& R) {
  Eigen::Matrix3d M;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) M(r, c) = R[r][c];
  return M;
}
inline btTransform to_bt(const Eigen::Isometry3d& T) {
  return btTransform(to_bt_matrix(T.linear()), to_bt(Eigen::Vector3d(T.translation())));
}

inline btQuaternion to_bt_quaternion(const Eigen::Matrix3d& R) {
  const Eigen::Quaterniond e(R);
  return btQuaternion(e.x(), e.y(), e.z(), e.w());
}

/// Principal inertial frame of a body (in its body frame) and the principal moments.
struct Principal {
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();
};

inline Principal principal_frame(const Inertia& inertia) {
  Principal p;
  p.frame.translation() = inertia.com;
  const Eigen::Matrix3d& I = inertia.inertia;
  const bool diagonal = I(0, 1) == 0.0 && I(0, 2) == 0.0 && I(1, 2) == 0.0 && I(1, 0) == 0.0 &&
                        I(2, 0) == 0.0 && I(2, 1) == 0.0;
  if (diagonal) {  // keep the body axes: no rounding from an eigen-decomposition
    p.moments = I.diagonal();
    return p;
  }
  Eigen::Matrix3d S = 0.5 * (I + I.transpose()), V;
  detail::symmetric_eigen(S, p.moments, V, true);  // columns of V: principal axes in the body frame
  if (V.determinant() < 0.0) V.col(2) = -V.col(2);  // a rotation, not a reflection
  p.frame.linear() = V;
  return p;
}

inline const char* unit_of(JointType type) { return type == JointType::kRevolute ? "rad/s" : "m/s"; }

}  // namespace bullet

struct Simulation::Impl {
  Model model;
  SimulationSettings settings;

  // Bullet objects, in construction order (destroyed in reverse by ~Impl).
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btMultiBodyConstraintSolver solver;
  btMultiBodyDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  std::unique_ptr<btMultiBody> mb;
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders;
  std::vector<std::unique_ptr<btCollisionObject>> obstacles;

  std::vector<bullet::Principal> principal;  // C_i per body
  Eigen::VectorXd q, qdot, tau;      // tau: clamped torques of the last step
  // External pushes for the next step (Simulation::push): force and torque about the COM,
  // world frame, per body; `pushed` says whether any is non-zero.
  std::vector<Eigen::Vector3d> push_force, push_torque;
  bool pushed = false;
  double time = 0.0;
  bool failed = false;
  std::string failure;
  SimulationSummary summary;
  std::vector<Contact> contacts;
  std::vector<Wrench> wrenches;
  Wrench no_wrench;

  // The armature (Body::armature), which Bullet's multibody has no term for: see
  // apply_armature(). Sized only when a joint has one.
  bool has_armature = false;
  Data dynamics;                  // opspace's own dynamics of `model`
  Eigen::VectorXd generalized;    // tau plus the pushes as joint torques
  Matrix6Xd push_jacobian;        // J0 of a pushed body's centre of mass
  Eigen::VectorXd armature_qdd;   // the armed acceleration the correction uses
  Eigen::VectorXd stage_q, stage_qdot, stage_qdd;  // RK4 stages of the armed dynamics
  std::vector<int> body_frame;    // frame index of each body's own link

  btAlignedObjectArray<btQuaternion> world_to_local;
  btAlignedObjectArray<btVector3> local_origin;
  btAlignedObjectArray<btScalar> scratch_r;
  btAlignedObjectArray<btVector3> scratch_v;
  btAlignedObjectArray<btMatrix3x3> scratch_m;
  btAlignedObjectArray<btScalar> unit_force, delta_acc;
  mutable btAlignedObjectArray<btVector3> omega, vel;

  Impl(const Model& m, const SimulationSettings& s) : model(m), settings(s), dynamics(m) {}
  ~Impl();
  int dof() const { return model.dof(); }

  // build.cpp: checks and world building; build() runs the steps below it in their order.
  void check_vector(const Eigen::Ref<const Eigen::VectorXd>& v, const char* what) const;
  void refresh_kinematics();
  void build();
  void build_multibody();     // one Bullet link per body, in its principal inertial frame
  void add_to_world();        // the multibody's settings, the world's gravity and solver
  void add_link_colliders();  // each body's collision shapes as one compound
  void size_state();          // the state at rest and every workspace a step uses
  void check_armature();      // the armatures, and apply_armature()'s workspaces where one is set
  // Bullet keeps at most 4 points per (link, obstacle) manifold: with the capacity reserved
  // here, gathering contacts in step() never allocates.
  void reserve_contacts();
  int add_obstacle(std::unique_ptr<btCollisionShape> shape, const btTransform& pose, const Material& m);

  // step.cpp: a step and what it reads back.
  Eigen::Isometry3d body_pose(int i) const;
  void gather_contacts();
  [[noreturn]] void fail(int joint, const std::string& cause);
  void step(const Eigen::Ref<const Eigen::VectorXd>& tau_requested);
  // Adds to each joint torque the armature's share: -armature_i qdd_i, qdd from opspace's
  // dynamics with the armature, (A + D) qdd = tau + pushes - b - g, at the step's start state.
  void apply_armature();
};

}  // namespace opspace
