#include "opspace/model/model.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "inertia_check.hpp"
#include "../math/small_decompositions.hpp"

namespace opspace {

namespace {

/// "'name' in model 'robot' (file)": the words every lookup error ends with.
std::string in_model(const Model& model) {
  return "model '" + model.name + "' (" + model.source + ")";
}

}  // namespace

int Model::frame_id(const std::string& frame_name) const {
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (frames[i].name == frame_name) return static_cast<int>(i);
  }
  throw std::out_of_range("no link '" + frame_name + "' in " + in_model(*this));
}

int Model::joint_id(const std::string& joint_name) const {
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].joint_name == joint_name) return static_cast<int>(i);
  }
  throw std::out_of_range("no moving joint '" + joint_name + "' in " + in_model(*this));
}

void Model::check_joint_vector(const Eigen::Ref<const Eigen::VectorXd>& v, const char* what) const {
  if (v.size() != dof()) {
    std::ostringstream s;
    s << what << " has " << v.size() << " entries, but " << in_model(*this) << " has " << dof()
      << " joints";
    throw std::invalid_argument(s.str());
  }
}

Data::Data(const Model& model)
    : body_pose(model.bodies.size(), Eigen::Isometry3d::Identity()),
      A(Eigen::MatrixXd::Zero(model.dof(), model.dof())),
      g(Eigen::VectorXd::Zero(model.dof())),
      b(Eigen::VectorXd::Zero(model.dof())),
      tau(Eigen::VectorXd::Zero(model.dof())),
      qdd(Eigen::VectorXd::Zero(model.dof())),
      A_factor(Eigen::MatrixXd::Zero(model.dof(), model.dof())),
      v(model.bodies.size(), Eigen::Matrix<double, 6, 1>::Zero()),
      a(model.bodies.size(), Eigen::Matrix<double, 6, 1>::Zero()),
      f(model.bodies.size(), Eigen::Matrix<double, 6, 1>::Zero()),
      S(model.bodies.size(), Eigen::Matrix<double, 6, 1>::Zero()),
      Ic(model.bodies.size()) {}

namespace detail {

std::string inertia_defect(const Eigen::Matrix3d& I) {
  if (!I.allFinite()) return "not finite";
  const double scale = std::max(1.0, I.cwiseAbs().maxCoeff());
  if (!(I - I.transpose()).isZero(1e-12 * scale)) return "not symmetric";
  Eigen::Matrix3d S = I, unused;
  Eigen::Vector3d mu;
  symmetric_eigen(S, mu, unused, false);
  if (mu.minCoeff() >= -1e-12 * scale) return "";
  std::ostringstream s;
  s << "not positive semi-definite (eigenvalues " << mu.transpose() << ")";
  return s.str();
}

}  // namespace detail

}  // namespace opspace
