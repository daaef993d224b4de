// A step of a Simulation and the contacts it reads back (simulation_impl.hpp).
#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "opspace/algorithms/dynamics.hpp"
#include "simulation_impl.hpp"

namespace opspace {

using namespace bullet;

Eigen::Isometry3d Simulation::Impl::body_pose(int i) const {
  Eigen::Isometry3d C = Eigen::Isometry3d::Identity();  // Bullet link (inertial) frame in world
  C.linear() = to_eigen(mb->localFrameToWorld(i, btMatrix3x3::getIdentity()));
  C.translation() = to_eigen(mb->localPosToWorld(i, btVector3(0, 0, 0)));
  return C * principal[i].frame.inverse();
}

void Simulation::Impl::gather_contacts() {
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

void Simulation::Impl::fail(int joint, const std::string& cause) {
  failed = true;
  std::ostringstream os;
  os << "opspace::Simulation of '" << model.name << "': joint '" << model.bodies[joint].joint_name
     << "' (index " << joint << ") " << cause << " at t = " << time << " s (step " << summary.steps
     << ")";
  failure = os.str();
  throw SimulationError(failure, model.bodies[joint].joint_name, time);
}

// Bullet integrates A qdd = tau' - b - g (+ pushes, contacts) with its own A, which has no
// armature D. Giving it tau' = tau - D qdd, with qdd solving (A + D) qdd = tau - b - g + pushes
// at the step's start state, makes its acceleration that of the robot with armature: exactly
// for the Euler integrator (one evaluation per step). RK4 evaluates Bullet's acceleration at
// four stages with the same tau': there qdd is the RK4 average of the armed accelerations at
// this step's own stages (with k1 alone the error would be first order in dt: a pendulum's
// period was 8e-4 short at 1 ms; with the average, 6e-7, tests/lib/test_armature.cpp).
// Contact impulses, solved by Bullet after this, see the robot without its armature.
void Simulation::Impl::apply_armature() {
  const int n = dof();
  generalized = tau;
  if (pushed) {
    forward_kinematics(model, dynamics, q);
    for (int i = 0; i < n; ++i) {
      if (push_force[i].isZero() && push_torque[i].isZero()) continue;
      point_jacobian(model, dynamics, body_frame[i], model.bodies[i].inertia.com, push_jacobian);
      for (int k = 0; k < n; ++k) {
        generalized(k) += push_jacobian.col(k).head<3>().dot(push_force[i]) +
                          push_jacobian.col(k).tail<3>().dot(push_torque[i]);
      }
    }
  }
  // k1: the armed acceleration at the start. Euler evaluates Bullet's once, there: done.
  armature_qdd = forward_dynamics(model, dynamics, q, qdot, generalized);
  if (settings.integrator == Integrator::kRK4) {
    // RK4 evaluates Bullet's at three more stage states with the same tau': the correction
    // uses the RK4 average of the armed accelerations over this step's own stages instead.
    const double dt = settings.dt;
    stage_qdd = armature_qdd;
    stage_qdot = qdot;
    armature_qdd /= 6.0;
    for (const auto& [fraction, weight] : {std::pair{0.5, 2.0}, std::pair{0.5, 2.0}, std::pair{1.0, 1.0}}) {
      stage_q = q + (fraction * dt) * stage_qdot;  // the previous stage's velocity
      stage_qdot = qdot + (fraction * dt) * stage_qdd;
      stage_qdd = forward_dynamics(model, dynamics, stage_q, stage_qdot, generalized);
      armature_qdd += (weight / 6.0) * stage_qdd;
    }
  }
  for (int i = 0; i < n; ++i) mb->addJointTorque(i, tau[i] - model.bodies[i].armature * armature_qdd(i));
}

void Simulation::Impl::step(const Eigen::Ref<const Eigen::VectorXd>& tau_requested) {
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
  }
  if (has_armature) {
    apply_armature();
  } else {
    for (int i = 0; i < n; ++i) mb->addJointTorque(i, tau[i]);
  }
  if (pushed) {  // Bullet clears link forces after the step, as it does joint torques
    for (int i = 0; i < n; ++i) {
      mb->addLinkForce(i, to_bt(push_force[i]));
      mb->addLinkTorque(i, to_bt(push_torque[i]));
      push_force[i].setZero();
      push_torque[i].setZero();
    }
    pushed = false;
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

}  // namespace opspace
