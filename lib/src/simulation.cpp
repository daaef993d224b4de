// A Bullet btMultiBody world built from a Model. See simulation.hpp and docs/simulation.md.
//
// Frames. Our body frame i is the URDF link frame (= the joint frame). Bullet's link frame is
// the link's principal inertial frame C_i: origin at the centre of mass, axes along the
// principal axes (Bullet wants a diagonal inertia). With P the parent's inertial frame (the
// identity for the fixed base), O the joint placement in the parent body frame and C the
// child's inertial frame in its body frame (bullet-notes.md, "Building from URDF"):
//   offsetInA = P^-1 O, offsetInB = C^-1,
//   rotParentToThis = rot(offsetInB) rot(offsetInA)^-1, axis = rot(offsetInB) axis_body,
//   parentComToThisPivotOffset = pos(offsetInA), thisPivotToThisComOffset = -pos(offsetInB).
#include "opspace/simulation.hpp"

#include <btBulletDynamicsCommon.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "small_decompositions.hpp"

static_assert(sizeof(btScalar) == 8,
              "Bullet must be the double-precision build (bullet-float64, BT_USE_DOUBLE_PRECISION)");

namespace opspace {

namespace {

btVector3 to_bt(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }
Eigen::Vector3d to_eigen(const btVector3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }

btMatrix3x3 to_bt_matrix(const Eigen::Matrix3d& R) {
  return btMatrix3x3(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2));
}
Eigen::Matrix3d to_eigen(const btMatrix3x3& R) {
  Eigen::Matrix3d M;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) M(r, c) = R[r][c];
  return M;
}
btTransform to_bt(const Eigen::Isometry3d& T) {
  return btTransform(to_bt_matrix(T.linear()), to_bt(Eigen::Vector3d(T.translation())));
}

btQuaternion to_bt_quaternion(const Eigen::Matrix3d& R) {
  const Eigen::Quaterniond e(R);
  return btQuaternion(e.x(), e.y(), e.z(), e.w());
}

/// Principal inertial frame of a body (in its body frame) and the principal moments.
struct Principal {
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();
};

Principal principal_frame(const Inertia& inertia) {
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

const char* unit_of(JointType type) { return type == JointType::kRevolute ? "rad/s" : "m/s"; }

}  // namespace

long SimulationSummary::total_clamped() const {
  long n = 0;
  for (const long c : clamped_steps) n += c;
  return n;
}

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

  std::vector<Principal> principal;  // C_i per body
  Eigen::VectorXd q, qdot, tau;      // tau: clamped torques of the last step
  double time = 0.0;
  bool failed = false;
  std::string failure;
  SimulationSummary summary;
  std::vector<Contact> contacts;
  std::vector<Wrench> wrenches;
  Wrench no_wrench;

  btAlignedObjectArray<btQuaternion> world_to_local;
  btAlignedObjectArray<btVector3> local_origin;
  btAlignedObjectArray<btScalar> scratch_r;
  btAlignedObjectArray<btVector3> scratch_v;
  btAlignedObjectArray<btMatrix3x3> scratch_m;
  btAlignedObjectArray<btScalar> unit_force, delta_acc;
  mutable btAlignedObjectArray<btVector3> omega, vel;

  Impl(const Model& m, const SimulationSettings& s) : model(m), settings(s) {}

  ~Impl() {
    for (auto& o : obstacles) world.removeCollisionObject(o.get());
    for (auto& c : colliders) world.removeCollisionObject(c.get());
    if (mb) world.removeMultiBody(mb.get());
  }

  int dof() const { return model.dof(); }

  void check_vector(const Eigen::Ref<const Eigen::VectorXd>& v, const char* what) const {
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

  void refresh_kinematics() {
    mb->forwardKinematics(world_to_local, local_origin);
    mb->updateCollisionObjectWorldTransforms(world_to_local, local_origin);
  }

  void build() {
    const int n = dof();
    for (int i = 0; i < n; ++i) {
      const Body& b = model.bodies[i];
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
      principal.push_back(principal_frame(b.inertia));
    }

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

    // Link colliders: one compound shape per body, children placed in the inertial frame.
    for (int i = 0; i < n; ++i) {
      std::unique_ptr<btCompoundShape> compound;
      for (const Shape& s : model.collisions) {
        if (s.body != i) continue;
        std::unique_ptr<btCollisionShape> shape;
        switch (s.kind) {
          case Shape::Kind::kSphere:
            shape = std::make_unique<btSphereShape>(s.radius);
            break;
          case Shape::Kind::kBox:
            shape = std::make_unique<btBoxShape>(to_bt(Eigen::Vector3d(0.5 * s.box_size)));
            break;
          case Shape::Kind::kCylinder:
            shape = std::make_unique<btCylinderShapeZ>(btVector3(s.radius, s.radius, 0.5 * s.length));
            break;
        }
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

    q = Eigen::VectorXd::Zero(n);
    qdot = Eigen::VectorXd::Zero(n);
    tau = Eigen::VectorXd::Zero(n);
    summary.clamped_steps.assign(n, 0);
    summary.max_requested_torque.assign(n, 0.0);
    wrenches.assign(n, Wrench{});
    world_to_local.resize(n + 1);
    local_origin.resize(n + 1);
    unit_force.resize(6 + n);
    delta_acc.resize(6 + n);
    omega.resize(n + 1);
    vel.resize(n + 1);
    reserve_contacts();
    refresh_kinematics();
  }

  // Bullet keeps at most 4 points per (link, obstacle) manifold: with the capacity reserved
  // here, gathering contacts in step() never allocates.
  void reserve_contacts() {
    contacts.reserve(4 * colliders.size() * std::max<size_t>(obstacles.size(), 1));
  }

  int add_obstacle(std::unique_ptr<btCollisionShape> shape, const btTransform& pose, const Material& m) {
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

  Eigen::Isometry3d body_pose(int i) const {
    Eigen::Isometry3d C = Eigen::Isometry3d::Identity();  // Bullet link (inertial) frame in world
    C.linear() = to_eigen(mb->localFrameToWorld(i, btMatrix3x3::getIdentity()));
    C.translation() = to_eigen(mb->localPosToWorld(i, btVector3(0, 0, 0)));
    return C * principal[i].frame.inverse();
  }

  void gather_contacts() {
    contacts.clear();
    for (auto& w : wrenches) w = Wrench{};
    const double dt = settings.dt;
    const int manifolds = dispatcher.getNumManifolds();
    for (int k = 0; k < manifolds; ++k) {
      const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(k);
      const auto* link0 = btMultiBodyLinkCollider::upcast(m->getBody0());
      const auto* link1 = btMultiBodyLinkCollider::upcast(m->getBody1());
      if ((link0 != nullptr) == (link1 != nullptr)) continue;  // self contact is off
      const bool body_is_a = link0 != nullptr;
      const int body = body_is_a ? link0->m_link : link1->m_link;
      const int obstacle = body_is_a ? m->getBody1()->getUserIndex() : m->getBody0()->getUserIndex();
      if (body < 0) continue;
      const double sign = body_is_a ? 1.0 : -1.0;  // m_normalWorldOnB points from B to A
      const Eigen::Vector3d origin = body_pose(body).translation();
      for (int p = 0; p < m->getNumContacts(); ++p) {
        const btManifoldPoint& pt = m->getContactPoint(p);
        const btVector3 impulse = pt.m_normalWorldOnB * pt.m_appliedImpulse +
                                  pt.m_lateralFrictionDir1 * pt.m_appliedImpulseLateral1 +
                                  pt.m_lateralFrictionDir2 * pt.m_appliedImpulseLateral2;
        if (pt.getDistance() > 0.0 && pt.m_appliedImpulse == 0.0) continue;  // not touching
        if (contacts.size() == contacts.capacity()) break;  // cannot happen: see reserve_contacts
        Contact c;
        c.body = body;
        c.obstacle = obstacle;
        c.position_on_body = to_eigen(body_is_a ? pt.m_positionWorldOnA : pt.m_positionWorldOnB);
        c.position_on_obstacle = to_eigen(body_is_a ? pt.m_positionWorldOnB : pt.m_positionWorldOnA);
        c.normal = sign * to_eigen(pt.m_normalWorldOnB);
        c.distance = pt.getDistance();
        c.force = (sign / dt) * to_eigen(impulse);
        wrenches[body].force += c.force;
        wrenches[body].moment += (c.position_on_body - origin).cross(c.force);
        contacts.push_back(c);
      }
    }
  }

  [[noreturn]] void fail(int joint, const std::string& cause) {
    failed = true;
    std::ostringstream os;
    os << "opspace::Simulation of '" << model.name << "': joint '" << model.bodies[joint].joint_name
       << "' (index " << joint << ") " << cause << " at t = " << time << " s (step " << summary.steps
       << ")";
    failure = os.str();
    throw SimulationError(failure, model.bodies[joint].joint_name, time);
  }

  void step(const Eigen::Ref<const Eigen::VectorXd>& tau_requested) {
    if (failed) throw SimulationError("opspace::Simulation: cannot step after a failure: " + failure, "", time);
    check_vector(tau_requested, "torque vector tau");
    const int n = dof();
    for (int i = 0; i < n; ++i) {
      const double t = tau_requested[i];
      const double limit = model.bodies[i].effort;
      summary.max_requested_torque[i] = std::max(summary.max_requested_torque[i], std::abs(t));
      if (limit > 0.0 && std::abs(t) > limit) {
        tau[i] = std::copysign(limit, t);
        ++summary.clamped_steps[i];
      } else {
        tau[i] = t;
      }
      mb->addJointTorque(i, tau[i]);
    }
    world.stepSimulation(settings.dt, 0, settings.dt);
    time = static_cast<double>(summary.steps + 1) * settings.dt;  // no accumulated rounding
    ++summary.steps;
    summary.time = time;
    for (int i = 0; i < n; ++i) {
      q[i] = mb->getJointPos(i);
      qdot[i] = mb->getJointVel(i);
    }
    for (int i = 0; i < n; ++i) {
      if (!std::isfinite(q[i]) || !std::isfinite(qdot[i])) {
        std::ostringstream os;
        os << "has a non-finite state (q = " << q[i] << ", qdot = " << qdot[i] << ")";
        fail(i, os.str());
      }
    }
    for (int i = 0; i < n; ++i) {
      if (std::abs(qdot[i]) > settings.max_joint_speed) {
        std::ostringstream os;
        os << "speed " << qdot[i] << " " << unit_of(model.bodies[i].type) << " exceeds the bound "
           << settings.max_joint_speed << " (SimulationSettings::max_joint_speed)";
        fail(i, os.str());
      }
    }
    gather_contacts();
  }
};

Simulation::Simulation(const Model& model, const SimulationSettings& settings)
    : impl_(std::make_unique<Impl>(model, settings)) {
  if (!(settings.dt > 0.0) || !std::isfinite(settings.dt)) {
    throw std::invalid_argument("opspace::Simulation: dt must be a positive number of seconds, got " +
                                std::to_string(settings.dt));
  }
  if (!(settings.max_joint_speed > 0.0)) {
    throw std::invalid_argument("opspace::Simulation: max_joint_speed must be positive, got " +
                                std::to_string(settings.max_joint_speed));
  }
  impl_->build();
}

Simulation::~Simulation() = default;

int Simulation::add_plane(const Eigen::Vector3d& normal, double offset, const Material& material) {
  const double norm = normal.norm();
  if (!(norm > 0.0) || !std::isfinite(norm) || !std::isfinite(offset)) {
    throw std::invalid_argument("opspace::Simulation::add_plane: the normal must be a finite non-zero vector "
                                "and the offset finite");
  }
  return impl_->add_obstacle(std::make_unique<btStaticPlaneShape>(to_bt(Eigen::Vector3d(normal / norm)), offset),
                             btTransform::getIdentity(), material);
}

int Simulation::add_box(const Eigen::Vector3d& size, const Eigen::Isometry3d& pose, const Material& material) {
  if (!(size.minCoeff() > 0.0) || !size.allFinite()) {
    throw std::invalid_argument("opspace::Simulation::add_box: edge lengths must be positive and finite");
  }
  return impl_->add_obstacle(std::make_unique<btBoxShape>(to_bt(Eigen::Vector3d(0.5 * size))), to_bt(pose),
                             material);
}

void Simulation::set_state(const Eigen::Ref<const Eigen::VectorXd>& q,
                           const Eigen::Ref<const Eigen::VectorXd>& qdot) {
  impl_->check_vector(q, "joint positions q");
  impl_->check_vector(qdot, "joint velocities qdot");
  for (int i = 0; i < impl_->dof(); ++i) {
    impl_->mb->setJointPos(i, q[i]);
    impl_->mb->setJointVel(i, qdot[i]);
  }
  impl_->q = q;
  impl_->qdot = qdot;
  impl_->refresh_kinematics();
  impl_->contacts.clear();
  for (auto& w : impl_->wrenches) w = Wrench{};
}

const Eigen::VectorXd& Simulation::q() const { return impl_->q; }
const Eigen::VectorXd& Simulation::qdot() const { return impl_->qdot; }
double Simulation::time() const { return impl_->time; }

void Simulation::step(const Eigen::Ref<const Eigen::VectorXd>& tau) { impl_->step(tau); }

Eigen::Isometry3d Simulation::body_pose(int body) const {
  if (body < 0 || body >= impl_->dof()) {
    if (body == -1) return Eigen::Isometry3d::Identity();
    throw std::out_of_range("opspace::Simulation::body_pose: body index " + std::to_string(body) +
                            " is not in [-1, " + std::to_string(impl_->dof()) + ")");
  }
  return impl_->body_pose(body);
}

int Simulation::link_body(const std::string& link) const {
  const Model& m = impl_->model;
  for (const Frame& f : m.frames)
    if (f.name == link) return f.body;
  for (int i = 0; i < m.dof(); ++i)
    if (m.bodies[i].link_name == link) return i;
  std::ostringstream os;
  os << "opspace::Simulation: no link named '" << link << "' in model '" << m.name << "'; links:";
  for (const Frame& f : m.frames) os << " " << f.name;
  if (m.frames.empty())
    for (const Body& b : m.bodies) os << " " << b.link_name;
  throw std::out_of_range(os.str());
}

Eigen::Isometry3d Simulation::link_pose(const std::string& link) const {
  const int body = link_body(link);
  for (const Frame& f : impl_->model.frames)
    if (f.name == link) return body_pose(body) * f.placement;
  return body_pose(body);
}

const std::vector<Contact>& Simulation::contacts() const { return impl_->contacts; }

const Wrench& Simulation::contact_wrench(int body) const {
  if (body == -1) return impl_->no_wrench;
  if (body < 0 || body >= impl_->dof()) {
    throw std::out_of_range("opspace::Simulation::contact_wrench: body index " + std::to_string(body) +
                            " is not in [-1, " + std::to_string(impl_->dof()) + ")");
  }
  return impl_->wrenches[body];
}

const Wrench& Simulation::contact_wrench(const std::string& link) const { return contact_wrench(link_body(link)); }

Energy Simulation::energy() const {
  const Impl& s = *impl_;
  const int n = s.dof();
  s.mb->compTreeLinkVelocities(&s.omega[0], &s.vel[0]);  // index 0: the base; link frames
  Energy e;
  for (int i = 0; i < n; ++i) {
    const double m = s.model.bodies[i].inertia.mass;
    const Eigen::Vector3d w = to_eigen(s.omega[i + 1]);
    const Eigen::Vector3d I = s.principal[i].moments;
    e.kinetic += 0.5 * m * s.vel[i + 1].length2() + 0.5 * (I.array() * w.array().square()).sum();
    e.potential -= m * s.model.gravity.dot(to_eigen(s.mb->localPosToWorld(i, btVector3(0, 0, 0))));
  }
  return e;
}

void Simulation::inverse_mass_matrix(Eigen::Ref<Eigen::MatrixXd> Minv) {
  Impl& s = *impl_;
  const int n = s.dof();
  if (Minv.rows() != n || Minv.cols() != n) {
    throw std::invalid_argument("opspace::Simulation::inverse_mass_matrix: output is " +
                                std::to_string(Minv.rows()) + "x" + std::to_string(Minv.cols()) + ", need " +
                                std::to_string(n) + "x" + std::to_string(n));
  }
  // dt = 0: the articulated-body pass fills Bullet's internal factors and moves nothing.
  s.mb->computeAccelerationsArticulatedBodyAlgorithmMultiDof(0.0, s.scratch_r, s.scratch_v, s.scratch_m,
                                                             false, false, false);
  for (int j = 0; j < n; ++j) {
    for (int k = 0; k < 6 + n; ++k) s.unit_force[k] = 0.0;
    s.unit_force[6 + j] = 1.0;  // layout: base torque (3), base force (3), joint torques
    s.mb->calcAccelerationDeltasMultiDof(&s.unit_force[0], &s.delta_acc[0], s.scratch_r, s.scratch_v);
    for (int i = 0; i < n; ++i) Minv(i, j) = s.delta_acc[6 + i];
  }
}

const SimulationSummary& Simulation::summary() const { return impl_->summary; }
const SimulationSettings& Simulation::settings() const { return impl_->settings; }
const Model& Simulation::model() const { return impl_->model; }
btMultiBody& Simulation::multibody() { return *impl_->mb; }
btMultiBodyDynamicsWorld& Simulation::world() { return impl_->world; }

}  // namespace opspace
