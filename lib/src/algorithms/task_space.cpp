// The storage of the operational-space quantities (opspace.hpp), sized once. Apart from
// operational_space() in opspace.cpp, which computes Jbar, an answer of problem 1a: a runner that
// only sizes a TaskSpace never links it (docs/grader.md, "The library's own answers").
#include <stdexcept>
#include <string>

#include "opspace/algorithms/opspace.hpp"

namespace opspace {

namespace {

using Eigen::Index;

Index checked(Index value, Index max, const char* what) {
  if (value < 1 || value > max) {
    throw std::invalid_argument(std::string("TaskSpace: ") + what + " is " + std::to_string(value) +
                                ", expected 1 to " + std::to_string(max));
  }
  return value;
}

}  // namespace

TaskSpace::TaskSpace(Eigen::Index task_dim, Eigen::Index dof)
    : Lambda(checked(task_dim, kMaxTaskDim, "the task dimension"), task_dim),
      Jbar(checked(dof, kMaxDof, "the number of joints"), task_dim),
      N(dof, dof),
      p(task_dim),
      Ainv_Jt(dof, task_dim),
      Lambda_inv(task_dim, task_dim),
      eigenvectors(task_dim, task_dim),
      eigenvalues(task_dim),
      inverse_eigenvalues(task_dim) {}

}  // namespace opspace
