#include "opspace/dynamics.hpp"

#include "opspace/kinematics.hpp"
#include "spatial.hpp"

namespace opspace {

namespace {

using spatial::Vector6d;

/// CRBA on the poses already in data: Ic_i = I_i + sum of its children's Ic, then
/// A_ji = S_j^T Ic_i S_i for every j on the path from i to the base (and A_ij = A_ji).
void crba_at_pose(const Model& model, Data& data) {
  const int n = model.dof();
  for (int i = 0; i < n; ++i) data.Ic[i] = spatial::body_inertia(model.bodies[i].inertia, data.body_pose[i]);
  data.A.setZero();
  for (int i = n - 1; i >= 0; --i) {  // children have larger indices: Ic[i] is complete here
    const Vector6d F = data.Ic[i] * data.S[i];
    data.A(i, i) = data.S[i].dot(F);
    for (int j = model.bodies[i].parent; j >= 0; j = model.bodies[j].parent) {
      data.A(j, i) = data.A(i, j) = data.S[j].dot(F);
    }
    const int parent = model.bodies[i].parent;
    if (parent >= 0) data.Ic[parent] += data.Ic[i];
  }
}

/// RNEA on the poses already in data, into `out`:
///   forward:  v_i = v_p + S_i qd_i,  a_i = a_p + S_i qdd_i + v_i xm S_i qd_i,  a_base = [-gravity; 0]
///             f_i = I_i a_i + v_i xf I_i v_i
///   backward: out_i = S_i^T f_i,  f_p += f_i
/// A null qdot or qdd stands for zero (so no zero vector needs to be allocated). The inertias
/// are applied without forming them (spatial::apply_inertia).
void rnea_at_pose(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>* qdot,
                  const Eigen::Ref<const Eigen::VectorXd>* qdd, const Eigen::Vector3d& gravity,
                  Eigen::VectorXd& out) {
  const int n = model.dof();
  Vector6d a_base;
  a_base << -gravity, Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) {
    const int parent = model.bodies[i].parent;
    const Inertia& inertia = model.bodies[i].inertia;
    const Eigen::Isometry3d& pose = data.body_pose[i];
    const Eigen::Vector3d c = pose * inertia.com;
    if (!qdot && !qdd) {
      // Gravity only: v = 0 and a_i = a_base, so f_i = I_i a_base = [m a0; c x m a0].
      data.v[i].setZero();
      data.a[i] = a_base;
      data.f[i].head<3>() = inertia.mass * a_base.head<3>();
      data.f[i].tail<3>() = c.cross(data.f[i].head<3>());
      continue;
    }
    const Vector6d vJ = qdot ? Vector6d(data.S[i] * (*qdot)(i)) : Vector6d::Zero();
    data.v[i] = parent < 0 ? vJ : Vector6d(data.v[parent] + vJ);
    data.a[i] = (parent < 0 ? a_base : data.a[parent]) + spatial::cross_motion(data.v[i], vJ);
    if (qdd) data.a[i] += data.S[i] * (*qdd)(i);
    const Eigen::Matrix3d Ic = pose.linear() * inertia.inertia * pose.linear().transpose();
    data.f[i] = spatial::apply_inertia(inertia.mass, c, Ic, data.a[i]) +
                spatial::cross_force(data.v[i], spatial::apply_inertia(inertia.mass, c, Ic, data.v[i]));
  }
  for (int i = n - 1; i >= 0; --i) {
    out(i) = data.S[i].dot(data.f[i]);
    const int parent = model.bodies[i].parent;
    if (parent >= 0) data.f[parent] += data.f[i];
  }
}

}  // namespace

const Eigen::MatrixXd& crba(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q) {
  forward_kinematics(model, data, q);
  crba_at_pose(model, data);
  return data.A;
}

const Eigen::VectorXd& generalized_gravity(const Model& model, Data& data,
                                           const Eigen::Ref<const Eigen::VectorXd>& q) {
  forward_kinematics(model, data, q);
  rnea_at_pose(model, data, nullptr, nullptr, model.gravity, data.g);
  return data.g;
}

void mass_matrix_and_gravity(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q) {
  forward_kinematics(model, data, q);
  crba_at_pose(model, data);
  rnea_at_pose(model, data, nullptr, nullptr, model.gravity, data.g);
}

const Eigen::VectorXd& coriolis_centrifugal(const Model& model, Data& data,
                                            const Eigen::Ref<const Eigen::VectorXd>& q,
                                            const Eigen::Ref<const Eigen::VectorXd>& qdot) {
  model.check_joint_vector(qdot, "coriolis_centrifugal: qdot");
  forward_kinematics(model, data, q);
  rnea_at_pose(model, data, &qdot, nullptr, Eigen::Vector3d::Zero(), data.b);
  return data.b;
}

const Eigen::VectorXd& rnea(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q,
                            const Eigen::Ref<const Eigen::VectorXd>& qdot,
                            const Eigen::Ref<const Eigen::VectorXd>& qdd) {
  model.check_joint_vector(qdot, "rnea: qdot");
  model.check_joint_vector(qdd, "rnea: qdd");
  forward_kinematics(model, data, q);
  rnea_at_pose(model, data, &qdot, &qdd, model.gravity, data.tau);
  return data.tau;
}

const Eigen::VectorXd& forward_dynamics(const Model& model, Data& data,
                                        const Eigen::Ref<const Eigen::VectorXd>& q,
                                        const Eigen::Ref<const Eigen::VectorXd>& qdot,
                                        const Eigen::Ref<const Eigen::VectorXd>& tau) {
  model.check_joint_vector(qdot, "forward_dynamics: qdot");
  model.check_joint_vector(tau, "forward_dynamics: tau");
  forward_kinematics(model, data, q);
  crba_at_pose(model, data);
  // qdd = A^-1 (tau - (b + g)), with b + g = RNEA(q, qdot, 0) computed into qdd itself.
  rnea_at_pose(model, data, &qdot, nullptr, model.gravity, data.qdd);
  data.qdd = tau - data.qdd;
  data.A_llt.compute(data.A);
  data.A_llt.solveInPlace(data.qdd);
  return data.qdd;
}

}  // namespace opspace
