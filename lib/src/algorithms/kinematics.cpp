#include "opspace/algorithms/kinematics.hpp"

#include <stdexcept>
#include <string>

#include "../math/spatial.hpp"
#include "body_spatial.hpp"

namespace opspace {

namespace {

/// Throws std::out_of_range unless `frame` indexes model.frames.
void check_frame(const Model& model, int frame) {
  if (frame < 0 || frame >= static_cast<int>(model.frames.size())) {
    throw std::out_of_range("frame index " + std::to_string(frame) + " out of range in model '" +
                            model.name + "'");
  }
}

}  // namespace

void forward_kinematics(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q) {
  model.check_joint_vector(q, "forward_kinematics: q");
  // oMi = oMparent * parentMjoint * jointMi(q_i), rotation and translation composed separately
  // (Eigen multiplies two Isometry3d as 4x4 matrices); then S_i from the new pose.
  for (int i = 0; i < model.dof(); ++i) {
    const Body& body = model.bodies[i];
    const Eigen::Isometry3d& placement = body.joint_placement;
    Eigen::Matrix3d R;
    Eigen::Vector3d t;
    if (body.parent < 0) {
      R = placement.linear();
      t = placement.translation();
    } else {
      const Eigen::Isometry3d& parent = data.body_pose[body.parent];
      R.noalias() = parent.linear() * placement.linear();
      t.noalias() = parent.translation() + parent.linear() * placement.translation();
    }
    if (body.type == JointType::kRevolute) {
      spatial::rotate_about_axis(R, body.axis, q(i));  // R * Rot(axis, q_i)
    } else {
      t.noalias() += R * (q(i) * body.axis);
    }
    Eigen::Isometry3d& pose = data.body_pose[i];
    pose.linear() = R;
    pose.translation() = t;
    data.S[i] = spatial::motion_subspace(body, R, t);
  }
}

Eigen::Isometry3d frame_pose(const Model& model, const Data& data, int frame) {
  check_frame(model, frame);
  const Frame& f = model.frames[frame];
  if (f.body < 0) return f.placement;
  // oMf = oMb * bMf, composed as rotation and translation (not as a 4x4 product).
  const Eigen::Isometry3d& body = data.body_pose[f.body];
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear().noalias() = body.linear() * f.placement.linear();
  pose.translation() = body.translation() + body.linear() * f.placement.translation();
  return pose;
}

Eigen::Vector3d point_position(const Model& model, const Data& data, int frame,
                               const Eigen::Vector3d& p) {
  check_frame(model, frame);
  const Frame& f = model.frames[frame];
  const Eigen::Vector3d in_body = f.placement * p;  // x = oMb (bMf p)
  return f.body < 0 ? in_body : data.body_pose[f.body] * in_body;
}

void point_jacobian(const Model& model, const Data& data, int frame, const Eigen::Vector3d& p,
                    Eigen::Ref<Matrix6Xd> J0) {
  if (J0.cols() != model.dof()) {
    throw std::invalid_argument("point_jacobian: J0 has " + std::to_string(J0.cols()) +
                                " columns, model '" + model.name + "' has " +
                                std::to_string(model.dof()) + " joints");
  }
  const Eigen::Vector3d x = point_position(model, data, frame, p);
  J0.setZero();
  // Column k for each joint k between the frame's body and the base: [v_O + w x x; w] of S_k.
  for (int k = model.frames[frame].body; k >= 0; k = model.bodies[k].parent) {
    const spatial::Vector6d& S = data.S[k];
    J0.col(k).head<3>() = S.head<3>() + S.tail<3>().cross(x);
    J0.col(k).tail<3>() = S.tail<3>();
  }
}

Vector6d point_velocity(const Model& model, const Data& data, int frame, const Eigen::Vector3d& p,
                        const Eigen::Ref<const Eigen::VectorXd>& qdot) {
  model.check_joint_vector(qdot, "point_velocity: qdot");
  const Eigen::Vector3d x = point_position(model, data, frame, p);
  // Body twist at O, V = sum_k S_k qdot_k over the chain; then v_x = v_O + w x x.
  spatial::Vector6d V = spatial::Vector6d::Zero();
  for (int k = model.frames[frame].body; k >= 0; k = model.bodies[k].parent) V += data.S[k] * qdot(k);
  Vector6d r;
  r << V.head<3>() + V.tail<3>().cross(x), V.tail<3>();
  return r;
}

Vector6d point_jacobian_dot_times_qdot(const Model& model, Data& data, int frame,
                                       const Eigen::Vector3d& p,
                                       const Eigen::Ref<const Eigen::VectorXd>& q,
                                       const Eigen::Ref<const Eigen::VectorXd>& qdot) {
  check_frame(model, frame);
  model.check_joint_vector(qdot, "point_jacobian_dot_times_qdot: qdot");
  forward_kinematics(model, data, q);
  // Velocity pass with qdd = 0: v_i = v_parent + S_i qd_i, a_i = a_parent + v_i xm S_i qd_i
  // (the spatial acceleration at O, since dS_i/dt = v_i xm S_i).
  for (int i = 0; i < model.dof(); ++i) {
    const int parent = model.bodies[i].parent;
    const spatial::Vector6d vJ = data.S[i] * qdot(i);
    data.v[i] = parent < 0 ? vJ : spatial::Vector6d(data.v[parent] + vJ);
    data.a[i] = spatial::cross_motion(data.v[i], vJ);
    if (parent >= 0) data.a[i] += data.a[parent];
  }
  const int body = model.frames[frame].body;
  if (body < 0) return Vector6d::Zero();
  // Classical acceleration of the body point at x: a_O + wdot x x + w x v_x.
  const Eigen::Vector3d x = point_position(model, data, frame, p);
  const Eigen::Vector3d w = data.v[body].tail<3>();
  const Eigen::Vector3d vx = data.v[body].head<3>() + w.cross(x);
  const Eigen::Vector3d wdot = data.a[body].tail<3>();
  Vector6d r;
  r << data.a[body].head<3>() + wdot.cross(x) + w.cross(vx), wdot;
  return r;
}

}  // namespace opspace
