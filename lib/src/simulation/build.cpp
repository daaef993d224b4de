// Building the Bullet world of a Simulation from a Model (simulation_impl.hpp).
//
// Frames. Our body frame i is the URDF link frame (= the joint frame). Bullet's link frame is
// the link's principal inertial frame C_i: origin at the centre of mass, axes along the
// principal axes (Bullet wants a diagonal inertia). With P the parent's inertial frame (the
// identity for the fixed base), O the joint placement in the parent body frame and C the
// child's inertial frame in its body frame (bullet-notes.md, "Building from URDF"):
//   offsetInA = P^-1 O, offsetInB = C^-1,
//   rotParentToThis = rot(offsetInB) rot(offsetInA)^-1, axis = rot(offsetInB) axis_body,
//   parentComToThisPivotOffset = pos(offsetInA), thisPivotToThisComOffset = -pos(offsetInB).
#include <sstream>

#include "simulation_impl.hpp"

namespace opspace {

using namespace bullet;

Simulation::Impl::~Impl() {
  for (auto& o : obstacles) world.removeCollisionObject(o.get());
  for (auto& c : colliders) world.removeCollisionObject(c.get());
  if (mb) world.removeMultiBody(mb.get());
}

void Simulation::Impl::check_vector(const Eigen::Ref<const Eigen::VectorXd>& v, const char* what) const {
  if (v.size() != dof()) {
    std::ostringstream os;
    os << "opspace::Simulation: " << what << " has " << v.size() << " entries, but model '"
       << model.name << "' has " << dof() << " joints";
    throw std::invalid_argument(os.str());
  }
  for (int i = 0; i < dof(); ++i) {
    if (!std::isfinite(v[i])) {
      std::ostringstream os;
      os << "opspace::Simulation: " << what << "[" << i << "] (joint '" << model.bodies[i].joint_name
         << "') is " << v[i] << ", not a finite number";
      throw std::invalid_argument(os.str());
    }
  }
}

void Simulation::Impl::refresh_kinematics() {
  mb->forwardKinematics(world_to_local, local_origin);
  mb->updateCollisionObjectWorldTransforms(world_to_local, local_origin);
}

namespace {

// Bullet's articulated-body algorithm needs each body after its parent and a positive mass.
void check_body(int i, const Body& b) {
  if (b.parent >= i || b.parent < -1) {
    std::ostringstream os;
    os << "opspace::Simulation: body " << i << " ('" << b.link_name << "') has parent " << b.parent
       << "; bodies must be in topological order (parent < index)";
    throw std::invalid_argument(os.str());
  }
  if (!(b.inertia.mass > 0.0)) {
    std::ostringstream os;
    os << "opspace::Simulation: body '" << b.link_name << "' has mass " << b.inertia.mass
       << "; Bullet's articulated-body algorithm needs a positive mass on every moving body";
    throw std::invalid_argument(os.str());
  }
}

// Bullet's shape of a collision shape, centred on its own origin (a cylinder along z).
std::unique_ptr<btCollisionShape> bullet_shape(const Shape& s) {
  switch (s.kind) {
    case Shape::Kind::kSphere:
      return std::make_unique<btSphereShape>(s.radius);
    case Shape::Kind::kBox:
      return std::make_unique<btBoxShape>(to_bt(Eigen::Vector3d(0.5 * s.box_size)));
    case Shape::Kind::kCylinder:
      return std::make_unique<btCylinderShapeZ>(btVector3(s.radius, s.radius, 0.5 * s.length));
  }
  return nullptr;
}

}  // namespace

void Simulation::Impl::build() {
  for (int i = 0; i < dof(); ++i) {
    check_body(i, model.bodies[i]);
    principal.push_back(principal_frame(model.bodies[i].inertia));
  }
  build_multibody();
  add_to_world();
  add_link_colliders();
  size_state();
  check_armature();
  reserve_contacts();
  refresh_kinematics();
}

// One link per body, in Bullet's link frame C_i (the frames above): offsetInA = P^-1 O,
// offsetInB = C^-1.
void Simulation::Impl::build_multibody() {
  const int n = dof();
  mb = std::make_unique<btMultiBody>(n, 1.0, btVector3(1.0, 1.0, 1.0), /*fixedBase=*/true,
                                     /*canSleep=*/false);
  mb->setBaseWorldTransform(btTransform::getIdentity());
  for (int i = 0; i < n; ++i) {
    const Body& b = model.bodies[i];
    const Eigen::Isometry3d P =
        b.parent < 0 ? Eigen::Isometry3d::Identity() : principal[b.parent].frame;
    const Eigen::Isometry3d in_a = P.inverse() * b.joint_placement;
    const Eigen::Isometry3d in_b = principal[i].frame.inverse();
    const Eigen::Matrix3d rot_parent_to_this = in_b.linear() * in_a.linear().transpose();
    const btVector3 axis = to_bt(Eigen::Vector3d(in_b.linear() * b.axis.normalized()));
    const btVector3 moments = to_bt(principal[i].moments);
    if (b.type == JointType::kRevolute) {
      mb->setupRevolute(i, b.inertia.mass, moments, b.parent, to_bt_quaternion(rot_parent_to_this), axis,
                        to_bt(Eigen::Vector3d(in_a.translation())), to_bt(Eigen::Vector3d(-in_b.translation())),
                        /*disableParentCollision=*/true);
    } else {
      mb->setupPrismatic(i, b.inertia.mass, moments, b.parent, to_bt_quaternion(rot_parent_to_this), axis,
                         to_bt(Eigen::Vector3d(in_a.translation())), to_bt(Eigen::Vector3d(-in_b.translation())),
                         /*disableParentCollision=*/true);
    }
  }
  mb->finalizeMultiDof();
}

// The multibody's settings (no damping, sleep or clamp that the Model does not have) and the
// world's gravity and solver.
void Simulation::Impl::add_to_world() {
  mb->setCanSleep(false);
  mb->setLinearDamping(0.0);
  mb->setAngularDamping(0.0);
  mb->setUseGyroTerm(true);
  mb->setMaxCoordinateVelocity(1e12);  // no silent clamp: step() checks max_joint_speed instead
  mb->setHasSelfCollision(false);
  mb->useRK4Integration(settings.integrator == Integrator::kRK4);
  world.addMultiBody(mb.get());
  world.setGravity(to_bt(model.gravity));
  world.getSolverInfo().m_numIterations = settings.solver_iterations;
}

// Link colliders: one compound shape per body, children placed in the inertial frame.
void Simulation::Impl::add_link_colliders() {
  for (int i = 0; i < dof(); ++i) {
    std::unique_ptr<btCompoundShape> compound;
    for (const Shape& s : model.collisions) {
      if (s.body != i) continue;
      std::unique_ptr<btCollisionShape> shape = bullet_shape(s);
      if (!compound) compound = std::make_unique<btCompoundShape>();
      compound->addChildShape(to_bt(Eigen::Isometry3d(principal[i].frame.inverse() * s.placement)),
                              shape.get());
      shapes.push_back(std::move(shape));
    }
    if (!compound) continue;
    auto col = std::make_unique<btMultiBodyLinkCollider>(mb.get(), i);
    col->setCollisionShape(compound.get());
    col->setFriction(1.0);     // Bullet multiplies the two sides' values: the obstacle decides
    col->setRestitution(1.0);
    col->setActivationState(DISABLE_DEACTIVATION);
    world.addCollisionObject(col.get(), btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
    mb->getLink(i).m_collider = col.get();
    shapes.push_back(std::move(compound));
    colliders.push_back(std::move(col));
  }
}

// The state at rest and every workspace a step uses, sized once: a step never allocates.
void Simulation::Impl::size_state() {
  const int n = dof();
  q = Eigen::VectorXd::Zero(n);
  qdot = Eigen::VectorXd::Zero(n);
  tau = Eigen::VectorXd::Zero(n);
  summary.clamped_steps.assign(n, 0);
  push_force.assign(n, Eigen::Vector3d::Zero());
  push_torque.assign(n, Eigen::Vector3d::Zero());
  summary.max_requested_torque.assign(n, 0.0);
  wrenches.assign(n, Wrench{});
  world_to_local.resize(n + 1);
  local_origin.resize(n + 1);
  unit_force.resize(6 + n);
  delta_acc.resize(6 + n);
  omega.resize(n + 1);
  vel.resize(n + 1);
}

// Each armature a finite number >= 0; with any non-zero, the workspaces of apply_armature().
void Simulation::Impl::check_armature() {
  for (const Body& b : model.bodies) {
    if (!(b.armature >= 0.0) || !std::isfinite(b.armature)) {
      throw std::invalid_argument("opspace::Simulation: joint '" + b.joint_name + "' has armature " +
                                  std::to_string(b.armature) + "; it must be a finite number >= 0");
    }
    has_armature = has_armature || b.armature > 0.0;
  }
  if (has_armature) {
    const int n = dof();
    generalized = armature_qdd = stage_q = stage_qdot = stage_qdd = Eigen::VectorXd::Zero(n);
    push_jacobian = Matrix6Xd::Zero(6, n);
    for (const Body& b : model.bodies) body_frame.push_back(model.frame_id(b.link_name));
  }
}

// Bullet keeps at most 4 points per (link, obstacle) manifold: with the capacity reserved
// here, gathering contacts in step() never allocates.
void Simulation::Impl::reserve_contacts() {
  contacts.reserve(4 * colliders.size() * std::max<size_t>(obstacles.size(), 1));
}

int Simulation::Impl::add_obstacle(std::unique_ptr<btCollisionShape> shape, const btTransform& pose, const Material& m) {
  if (!(m.friction >= 0.0) || !(m.restitution >= 0.0) || !(m.restitution <= 1.0)) {
    std::ostringstream os;
    os << "opspace::Simulation: material friction " << m.friction << " and restitution " << m.restitution
       << ": need friction >= 0 and 0 <= restitution <= 1";
    throw std::invalid_argument(os.str());
  }
  auto obj = std::make_unique<btCollisionObject>();
  obj->setCollisionShape(shape.get());
  obj->setWorldTransform(pose);
  obj->setCollisionFlags(obj->getCollisionFlags() | btCollisionObject::CF_STATIC_OBJECT);
  obj->setFriction(m.friction);
  obj->setRestitution(m.restitution);
  const int id = static_cast<int>(obstacles.size());
  obj->setUserIndex(id);
  world.addCollisionObject(obj.get(), btBroadphaseProxy::StaticFilter,
                           btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
  shapes.push_back(std::move(shape));
  obstacles.push_back(std::move(obj));
  reserve_contacts();
  return id;
}

}  // namespace opspace
