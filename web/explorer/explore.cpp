#include "explore.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/algorithms/linalg.hpp"
#include "page_json.hpp"

namespace opspace::explore {

namespace {

using Matrix3Xd = Eigen::Matrix<double, 3, Eigen::Dynamic>;

/// Jv of the tip at the configuration of the last forward_kinematics.
Matrix3Xd linear_jacobian(const Model& model, const Data& data, const Tip& tip) {
  Matrix6Xd J0(6, model.dof());
  point_jacobian(model, data, tip.frame, tip.point, J0);
  return J0.topRows<3>();
}

/// J+ or Jbar of Jv at q (runs forward_kinematics and, for Jbar, crba).
Eigen::MatrixXd right_inverse(const Model& model, Data& data, const Tip& tip,
                              const Eigen::Ref<const Eigen::VectorXd>& q, Inverse inverse, Matrix3Xd& Jv) {
  forward_kinematics(model, data, q);
  Jv = linear_jacobian(model, data, tip);
  if (inverse == Inverse::kPseudoInverse) return pseudo_inverse(Jv);
  return dynamically_consistent_inverse(Jv, crba(model, data, q));
}

/// x(q) of the tip (runs forward_kinematics).
Eigen::Vector3d tip_position(const Model& model, Data& data, const Tip& tip, const Eigen::Ref<const Eigen::VectorXd>& q) {
  forward_kinematics(model, data, q);
  return point_position(model, data, tip.frame, tip.point);
}

int steps_for(double s) { return std::max(1, static_cast<int>(std::ceil(std::abs(s) / kStep))); }

}  // namespace

TipView view(const Model& model, Data& data, const Tip& tip, const Eigen::Ref<const Eigen::VectorXd>& q) {
  model.check_joint_vector(q, "explore::view: q");
  TipView v;
  v.singularities = analyse_singularities(model, data, tip.frame, tip.point, q);  // runs forward kinematics
  v.x = point_position(model, data, tip.frame, tip.point);
  v.Jv = linear_jacobian(model, data, tip);
  v.velocity_axes = v.singularities.linear.U;
  v.velocity_radii = v.singularities.linear.sigma;
  // Lambda_v^-1 = Jv A^-1 Jv^T, through the Cholesky factor of A: no inverse of A is formed.
  const Eigen::MatrixXd& A = crba(model, data, q);
  const Matrix3Xd AinvJt = A.llt().solve(v.Jv.transpose()).transpose();
  const Eigen::Matrix3d Lambda_inv = v.Jv * AinvJt.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(Lambda_inv);
  const double largest = eig.eigenvalues().maxCoeff();
  for (int i = 0; i < 3; ++i) {  // eigenvalues increase: radii decrease
    const double mu = eig.eigenvalues()(i);
    v.mass_radii(i) = mu > kSingularValueTolerance * largest ? 1.0 / std::sqrt(mu)
                                                              : std::numeric_limits<double>::infinity();
  }
  v.mass_axes = eig.eigenvectors();
  return v;
}

Eigen::VectorXd tip_motion(const Model& model, Data& data, const Tip& tip,
                           const Eigen::Ref<const Eigen::VectorXd>& q0, const Eigen::Vector3d& u, double s,
                           Inverse inverse) {
  model.check_joint_vector(q0, "explore::tip_motion: q");
  const Eigen::Vector3d x0 = tip_position(model, data, tip, q0);
  const int n = steps_for(s);
  Eigen::VectorXd q = q0;
  Matrix3Xd Jv;
  for (int k = 1; k <= n; ++k) {
    // q <- q + J_inv (x_d(s_k) - x(q)): the step along u and the correction of the last one's drift.
    const Eigen::MatrixXd J_inv = right_inverse(model, data, tip, q, inverse, Jv);
    const Eigen::Vector3d x_d = x0 + (s * k / n) * u;
    q += J_inv * (x_d - point_position(model, data, tip.frame, tip.point));
  }
  return q;
}

Eigen::VectorXd self_motion(const Model& model, Data& data, const Tip& tip,
                            const Eigen::Ref<const Eigen::VectorXd>& q0, int j, double s, Inverse inverse) {
  model.check_joint_vector(q0, "explore::self_motion: q");
  if (j < 0 || j >= model.dof()) {
    throw std::invalid_argument("explore::self_motion: joint index " + std::to_string(j) + " is not in [0, " +
                                std::to_string(model.dof()) + ") for model '" + model.name + "'");
  }
  const Eigen::Vector3d x0 = tip_position(model, data, tip, q0);
  const int n = steps_for(s);
  Eigen::VectorXd q = q0;
  Matrix3Xd Jv;
  for (int k = 1; k <= n; ++k) {
    // q <- q + (I - J_inv Jv) e_j h, then J_inv (x0 - x(q)) takes back the second-order drift.
    Eigen::MatrixXd J_inv = right_inverse(model, data, tip, q, inverse, Jv);
    q += (s / n) * (Eigen::VectorXd::Unit(model.dof(), j) - J_inv * Jv.col(j));
    J_inv = right_inverse(model, data, tip, q, inverse, Jv);
    q += J_inv * (x0 - point_position(model, data, tip.frame, tip.point));
  }
  return q;
}

// ---- JSON for the page ----

Json json_number(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

namespace {

Json vector_json(const Eigen::Ref<const Eigen::VectorXd>& v) {
  Json out = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(json_number(v(i)));
  return out;
}

/// A matrix as an array of its columns (the page reads directions as columns).
Json columns_json(const Eigen::Ref<const Eigen::MatrixXd>& M) {
  Json out = Json::array();
  for (Eigen::Index c = 0; c < M.cols(); ++c) out.push_back(vector_json(M.col(c)));
  return out;
}

/// Body poses [px, py, pz, qx, qy, qz, qw], one array per body, at the last forward kinematics.
Json poses(const Data& data) {
  Json out = Json::array();
  for (const Eigen::Isometry3d& X : data.body_pose) {
    const Eigen::Quaterniond r(X.rotation());
    const Eigen::Vector3d p = X.translation();
    out.push_back(Json::array({json_number(p.x()), json_number(p.y()), json_number(p.z()), json_number(r.x()),
                               json_number(r.y()), json_number(r.z()), json_number(r.w())}));
  }
  return out;
}

Json moved(const Model& model, Data& data, const Tip& tip, const Request& r, Inverse inverse) {
  Eigen::VectorXd q = self_motion(model, data, tip, r.q, r.self_joint, r.self_s, inverse);
  q = tip_motion(model, data, tip, q, r.u, r.tip_s, inverse);
  forward_kinematics(model, data, q);
  Json out{{"q", vector_json(q)}, {"tip", vector_json(point_position(model, data, tip.frame, tip.point))}};
  out["poses"] = poses(data);
  return out;
}

}  // namespace

std::string view_json(const Model& model, Data& data, const Tip& tip, const Request& request) {
  require_finite(request.q, "explorer request q");
  require_finite(request.u, "explorer request u");
  if (!std::isfinite(request.tip_s) || !std::isfinite(request.self_s)) {
    throw std::invalid_argument("explorer request: the motion sliders hold a NaN or an infinity");
  }
  if (request.u.norm() == 0.0) throw std::invalid_argument("explorer request: the tip-motion direction is zero");
  Request r = request;
  r.u.normalize();
  const TipView v = view(model, data, tip, r.q);
  const SingularityAnalysis& s = v.singularities;
  Json singular = Json::array();
  for (int i = 0; i < 3 - s.linear.rank; ++i) {
    singular.push_back(Json{{"u", vector_json(s.linear.singular().col(i))}, {"type", static_cast<int>(s.type(i))}});
  }
  Json j{{"x", vector_json(v.x)},
         {"Jv", columns_json(v.Jv)},
         {"velocity", {{"axes", columns_json(v.velocity_axes)}, {"radii", vector_json(v.velocity_radii)}}},
         {"mass", {{"axes", columns_json(v.mass_axes)}, {"radii", vector_json(v.mass_radii)}}},  // null: unbounded
         {"rank", s.linear.rank},
         {"type_one", s.type_one},
         {"singular", std::move(singular)},
         {"angular_sigma", vector_json(s.angular.sigma)}};
  forward_kinematics(model, data, r.q);
  j["poses"] = poses(data);
  j["pseudo_inverse"] = moved(model, data, tip, r, Inverse::kPseudoInverse);
  j["dynamically_consistent"] = moved(model, data, tip, r, Inverse::kDynamicallyConsistent);
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace opspace::explore
