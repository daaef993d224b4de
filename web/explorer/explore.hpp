/// @file explore.hpp
/// What the explorer page draws at a configuration q, computed by the library (compiled
/// natively for the tests and the page's data, and to WebAssembly for the page itself).
///
/// At the tip point x (point p on frame `frame`), with Jv its 3 x n linear Jacobian and A(q)
/// the mass matrix:
///   velocity ellipsoid  {Jv dq : |dq| <= 1} = {v : v^T (Jv Jv^T)^+ v <= 1}: semi-axes
///                       sigma_i along u_i, the SVD Jv = U diag(sigma) V^T;
///   mass ellipsoid      {v : v^T Lambda_v^-1 v <= 1}, Lambda_v^-1 = Jv A^-1 Jv^T: its radius
///                       along a unit u is sqrt(m_u), m_u = 1 / (u^T Lambda_v^-1 u) the
///                       effective mass the tip presents along u (infinite along a singular
///                       direction: no force there accelerates the tip);
///   singular directions and their types (singularity.hpp, problem 4).
/// And two motions from q, one per right inverse J_inv of Jv (J+ or Jbar = A^-1 Jv^T Lambda_v):
///   tip motion   dq/ds = J_inv u: the tip moves by s along the unit u (problem 1a-vi);
///   self-motion  dq/ds = (I - J_inv Jv) e_j: the null-space motion that joint j asks for,
///                with the tip held still.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "opspace/model/model.hpp"
#include "opspace/algorithms/singularity.hpp"

namespace opspace::explore {

/// The two right inverses the page compares.
enum class Inverse { kPseudoInverse, kDynamicallyConsistent };

/// The robot the page explores: a Model and its tip point.
struct Tip {
  int frame = -1;                                 ///< frame of the tip link
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< tip point in that frame
};

/// The ellipsoids and singular directions at one configuration.
struct TipView {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  ///< tip position, base frame
  Eigen::Matrix<double, 3, Eigen::Dynamic> Jv;  ///< linear Jacobian of the tip
  Eigen::Matrix3d velocity_axes;                ///< U of Jv's SVD (columns)
  Eigen::Vector3d velocity_radii;               ///< sigma, decreasing (m/s per unit |qdot|)
  Eigen::Matrix3d mass_axes;                    ///< eigenvectors of Lambda_v^-1 (columns)
  Eigen::Vector3d mass_radii;                   ///< sqrt(m_u) along them (kg^1/2); inf where singular
  SingularityAnalysis singularities;            ///< linear and angular directions, types
};

/// The view at q. Allocates (an analysis for the page, not a control tick).
TipView view(const Model& model, Data& data, const Tip& tip, const Eigen::Ref<const Eigen::VectorXd>& q);

/// The configuration after a tip motion of s metres along unit u, through `inverse`,
/// integrated in steps of at most kStep.
Eigen::VectorXd tip_motion(const Model& model, Data& data, const Tip& tip,
                           const Eigen::Ref<const Eigen::VectorXd>& q, const Eigen::Vector3d& u, double s,
                           Inverse inverse);

/// The configuration after the self-motion that joint j asks for, s (rad or m) of it, through
/// `inverse`'s projector, the tip held still.
Eigen::VectorXd self_motion(const Model& model, Data& data, const Tip& tip,
                            const Eigen::Ref<const Eigen::VectorXd>& q, int j, double s, Inverse inverse);

/// Largest integration step of the two motions (m or rad).
inline constexpr double kStep = 0.01;

/// What the page asks for at one configuration (the sliders' state).
struct Request {
  Eigen::VectorXd q;                           ///< joint positions
  Eigen::Vector3d u = Eigen::Vector3d::UnitX(); ///< tip-motion direction (normalised here)
  double tip_s = 0.0;                          ///< tip motion (m)
  int self_joint = 0;                          ///< joint whose self-motion is asked for
  double self_s = 0.0;                         ///< self-motion (rad or m)
};

/// Everything the page draws for `request`, as JSON (page_json.hpp: exact doubles, null for an
/// unbounded mass radius): the view, each body's pose, and for J+ and Jbar the moved
/// configuration, its body poses and its tip. Throws std::invalid_argument for a wrong-sized or
/// non-finite request.
std::string view_json(const Model& model, Data& data, const Tip& tip, const Request& request);

}  // namespace opspace::explore
