# The reference 1a, except that Jbar comes from the library with no reference to it at all: the
# call of opspace::symmetric_pseudo_inverse, allowed, pulled in the object file that held Jbar too
# (before the split), and the runner found opspace::dynamically_consistent_inverse in its own
# symbol table (own_symbol.inc). The earlier grader gave 23/23. Now no allowed helper shares an
# object file with an answer and the runner holds only what it reaches (--gc-sections): the
# lookup finds nothing, the submission answers zero, and Jbar's tests (vi's Jbar and split,
# 5 points) earn nothing: 18. (Had the answer been in the runner, the grader would name it.)
set(TARGET p1a.cpp)
file(READ "${CMAKE_CURRENT_LIST_DIR}/own_symbol.inc" PREPEND)
string(PREPEND PREPEND "#include <opspace/algorithms/linalg.hpp>\n")
set(FROM "Eigen::Vector2d inertia_weighted_inverse(const Eigen::RowVector2d& J, const Eigen::Matrix2d& A) {")
set(TO [=[Eigen::Vector2d inertia_weighted_inverse(const Eigen::RowVector2d& J, const Eigen::Matrix2d& A) {
  (void)opspace::symmetric_pseudo_inverse(Eigen::MatrixXd(A), 1e-10);
  using Inverse = Eigen::MatrixXd (*)(const Eigen::Ref<const Eigen::MatrixXd>&, const Eigen::Ref<const Eigen::MatrixXd>&, double);
  const auto library = reinterpret_cast<Inverse>(own_symbol(
      "_ZN7opspace30dynamically_consistent_inverseERKN5Eigen3RefIKNS0_6MatrixIdLin1ELin1ELi0ELin1ELin1EEELi0ENS0_11OuterStrideILin1EEEEES9_d"));
  if (!library) return Eigen::Vector2d::Zero();
  return library(Eigen::MatrixXd(J), Eigen::MatrixXd(A), 1e-10);]=])
