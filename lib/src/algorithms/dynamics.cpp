#include "opspace/algorithms/dynamics.hpp"

#include <stdexcept>

#include "opspace/algorithms/kinematics.hpp"
#include "../math/small_decompositions.hpp"
#include "../math/spatial.hpp"
#include "body_spatial.hpp"

namespace opspace {

namespace {

using spatial::Vector6d;

/// The torque g_i that holds the subtree of body i, of mass M and first moment H, against
/// gravity: in RNEA terms the base accelerates by a0 = -gravity, the subtree's force about O is
/// [M a0; H x a0] and g_i = S_i . [M a0; H x a0].
double gravity_torque(const Vector6d& S, const SpatialInertia& subtree, const Eigen::Vector3d& a0) {
  return S.head<3>().dot(subtree.m * a0) + S.tail<3>().dot(subtree.h.cross(a0));
}

/// CRBA on the poses already in data, in the base frame: Ic_i = I_i + the Ic of its children,
/// then A_ji = S_j^T Ic_i S_i for every j on the path from i to the base (and A_ij = A_ji);
/// the joint's armature (Body::armature) adds to A_ii.
/// The inertias are kept as (m, h, I) (SpatialInertia): a sum costs 13 additions, not 36.
/// With `g`, also g(q) from the same composite inertias (gravity_torque).
void crba_at_pose(const Model& model, Data& data, Eigen::VectorXd* g) {
  const int n = model.dof();
  for (int i = 0; i < n; ++i) spatial::body_inertia(model.bodies[i].inertia, data.body_pose[i], data.Ic[i]);
  const Eigen::Vector3d a0 = -model.gravity;
  data.A.setZero();
  for (int i = n - 1; i >= 0; --i) {  // children have larger indices: Ic[i] is complete here
    const Vector6d F = spatial::apply_inertia(data.Ic[i], data.S[i]);
    data.A(i, i) = data.S[i].dot(F) + model.bodies[i].armature;
    for (int j = model.bodies[i].parent; j >= 0; j = model.bodies[j].parent) {
      data.A(j, i) = data.A(i, j) = data.S[j].dot(F);
    }
    if (g) (*g)(i) = gravity_torque(data.S[i], data.Ic[i], a0);
    const int parent = model.bodies[i].parent;
    if (parent >= 0) spatial::add_inertia(data.Ic[parent], data.Ic[i]);
  }
}

/// g(q) alone on the poses already in data: only the masses and first moments of the subtrees
/// (data.Ic's m and h), accumulated exactly as crba_at_pose does, so that both give the same bits.
void gravity_at_pose(const Model& model, Data& data, Eigen::VectorXd& g) {
  const int n = model.dof();
  for (int i = 0; i < n; ++i) {
    const Inertia& in = model.bodies[i].inertia;
    const Eigen::Isometry3d& pose = data.body_pose[i];
    const Eigen::Matrix3d R = pose.linear();
    const Eigen::Vector3d c = R * in.com + pose.translation();  // as in spatial::body_inertia
    data.Ic[i].m = in.mass;
    data.Ic[i].h = in.mass * c;
  }
  const Eigen::Vector3d a0 = -model.gravity;
  for (int i = n - 1; i >= 0; --i) {
    g(i) = gravity_torque(data.S[i], data.Ic[i], a0);
    const int parent = model.bodies[i].parent;
    if (parent >= 0) {
      data.Ic[parent].m += data.Ic[i].m;
      data.Ic[parent].h += data.Ic[i].h;
    }
  }
}

/// RNEA on the poses already in data, into `out`:
///   forward:  v_i = v_p + S_i qd_i,  a_i = a_p + S_i qdd_i + v_i xm S_i qd_i,  a_base = [-gravity; 0]
///             f_i = I_i a_i + v_i xf I_i v_i
///   backward: out_i = S_i^T f_i + armature_i qdd_i,  f_p += f_i
/// A null qdot or qdd stands for zero (so no zero vector needs to be allocated). The inertias
/// are applied without forming them (spatial::apply_inertia). (g alone: gravity_at_pose.)
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
    if (qdd) out(i) += model.bodies[i].armature * (*qdd)(i);  // the rotor's own torque
    const int parent = model.bodies[i].parent;
    if (parent >= 0) data.f[parent] += data.f[i];
  }
}

}  // namespace

const Eigen::MatrixXd& crba(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q) {
  forward_kinematics(model, data, q);
  crba_at_pose(model, data, nullptr);
  return data.A;
}

const Eigen::VectorXd& generalized_gravity(const Model& model, Data& data,
                                           const Eigen::Ref<const Eigen::VectorXd>& q) {
  forward_kinematics(model, data, q);
  gravity_at_pose(model, data, data.g);
  return data.g;
}

void mass_matrix_and_gravity(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q) {
  forward_kinematics(model, data, q);
  crba_at_pose(model, data, &data.g);
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
  crba_at_pose(model, data, nullptr);
  // qdd = A^-1 (tau - (b + g)), with b + g = RNEA(q, qdot, 0) computed into qdd itself.
  rnea_at_pose(model, data, &qdot, nullptr, model.gravity, data.qdd);
  data.qdd = tau - data.qdd;
  data.A_factor = data.A;
  if (!detail::cholesky_in_place(data.A_factor)) {
    throw std::invalid_argument("forward_dynamics: A(q) is not positive definite (a massless chain?)");
  }
  detail::cholesky_solve_in_place(data.A_factor, data.qdd);
  return data.qdd;
}

}  // namespace opspace
