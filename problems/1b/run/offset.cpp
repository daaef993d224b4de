// Problem 1b: the tip's static offset under a push (problems/1b/run/offset.hpp).
#include <problems/1b/run/offset.hpp>

#include <Eigen/Cholesky>

namespace opspace::live {

Eigen::Vector3d p1b_static_tip_offset(const hw2::p1b::State& s, const Eigen::Ref<const Eigen::VectorXd>& tau_push,
                                      double kpx) {
  // Fixed sizes: no heap in the control tick.
  const Eigen::LLT<hw2::p1b::Matrix6d> A(s.A);
  const hw2::p1b::Vector6d tau = tau_push;
  return s.Jv * A.solve(tau) / kpx;
}

}  // namespace opspace::live
