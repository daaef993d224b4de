# The reference 1a, except that J# comes from the library through an alias: a weakref under
# another name refers to opspace::weighted_inverse by its mangled name, weakly; the call of
# opspace::require_size, allowed, pulled in the object file that held J# too (before the split).
# The earlier grader gave 23/23. Now the grader names the reference and J#'s tests (v, vi's Jbar
# that the reference computes with J#, vi's split: 8 points) earn nothing: 15.
set(TARGET p1a.cpp)
set(PREPEND [=[#include <opspace/algorithms/linalg.hpp>
static Eigen::MatrixXd library_weighted(const Eigen::Ref<const Eigen::MatrixXd>&, const Eigen::Ref<const Eigen::MatrixXd>&,
                                        double)
    __attribute__((weakref("_ZN7opspace16weighted_inverseERKN5Eigen3RefIKNS0_6MatrixIdLin1ELin1ELi0ELin1ELin1EEELi0ENS0_11OuterStrideILin1EEEEES9_d")));
]=])
set(FROM "Eigen::Vector2d weighted_inverse(const Eigen::RowVector2d& J, const Eigen::Matrix2d& W) {")
set(TO [=[Eigen::Vector2d weighted_inverse(const Eigen::RowVector2d& J, const Eigen::Matrix2d& W) {
  opspace::require_size(W, 2, 2, "W");
  return library_weighted(Eigen::MatrixXd(J), Eigen::MatrixXd(W), 1e-10);]=])
