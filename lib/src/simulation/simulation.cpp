// A Bullet btMultiBody world built from a Model: the public class (simulation.hpp), over its
// state and world (simulation_impl.hpp). See docs/simulation.md.
#include <sstream>

#include "simulation_impl.hpp"

namespace opspace {

using namespace bullet;

long SimulationSummary::total_clamped() const {
  long n = 0;
  for (const long c : clamped_steps) n += c;
  return n;
}

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

void Simulation::push(int body, const Eigen::Vector3d& force, const Eigen::Vector3d& point) {
  if (body < 0 || body >= impl_->dof()) {
    throw std::out_of_range("opspace::Simulation::push: body index " + std::to_string(body) + " is not one of the " +
                            std::to_string(impl_->dof()) + " bodies of '" + impl_->model.name + "'");
  }
  if (!force.allFinite() || !point.allFinite()) {
    throw std::invalid_argument("opspace::Simulation::push: the force and its point must be finite");
  }
  // Bullet applies a link force at the link's centre of mass (its inertial frame's origin).
  const Eigen::Vector3d com = bullet::to_eigen(impl_->mb->localPosToWorld(body, btVector3(0, 0, 0)));
  impl_->push_force[body] += force;
  impl_->push_torque[body] += (point - com).cross(force);
  impl_->pushed = true;
}

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
    e.kinetic += 0.5 * s.model.bodies[i].armature * s.qdot[i] * s.qdot[i];  // the rotor's
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
