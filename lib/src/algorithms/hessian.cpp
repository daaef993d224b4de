// The position Hessian of a point: kinematics the library's scenarios need (problem 4's
// Kinematics::H). Apart from singularity.cpp, whose analysis answers problem 4's questions i-iv
// and is left out of a student handout (scripts/handout).
#include <stdexcept>
#include <string>

#include "opspace/algorithms/kinematics.hpp"
#include "opspace/algorithms/singularity.hpp"

namespace opspace {

void point_position_hessian(const Model& model, const Data& data, int frame, const Eigen::Vector3d& p,
                            Eigen::Ref<Eigen::MatrixXd> H) {
  const Eigen::Index n = model.dof();
  if (H.rows() != 3 * n || H.cols() != n) {
    throw std::invalid_argument("point_position_hessian: H is " + std::to_string(H.rows()) + " x " +
                                std::to_string(H.cols()) + ", expected " + std::to_string(3 * n) + " x " +
                                std::to_string(n) + " for model '" + model.name + "'");
  }
  Matrix6Xd J0(6, n);
  point_jacobian(model, data, frame, p, J0);
  // Columns of joints that do not carry the frame are zero, so their entries come out zero.
  // Along the chain a smaller index is an ancestor (bodies are in topological order).
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = i; j < n; ++j) {
      const Eigen::Vector3d c = J0.col(i).tail<3>().cross(J0.col(j).head<3>());  // Jw_i x Jv_j
      for (Eigen::Index k = 0; k < 3; ++k) {
        H(k * n + i, j) = c(k);
        H(k * n + j, i) = c(k);
      }
    }
  }
}

}  // namespace opspace
