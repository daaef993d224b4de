// Known mistakes of problem 5.
#include "mistakes.hpp"

namespace opspace::grading {

std::vector<Mistake> mistakes_5() {
  return {
      {"Lambda = J A^-1 J^T: the mobility, its inverse forgotten",
       "Lambda = (J A^-1 J^T)^-1, the inverse of the mobility",
       [](Hw2Api& api) {
         api.p5.task_inertia = [](const Eigen::Matrix2d& J, const Eigen::Matrix2d& A) {
           return Eigen::Matrix2d(J * A.inverse() * J.transpose());
         };
       },
       {"i. the task inertia is (J A^-1 J^T)^-1 at random Jacobians and mass matrices"}},
  };
}

}  // namespace opspace::grading
