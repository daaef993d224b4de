# The reference 1a, except that J# comes from the library with no reference to it: the file uses
# a template instance that only the library's object file of J# defined,
# opspace::detail::cholesky_solve_in_place<MatrixXd, MatrixXd>, which pulled that object file
# in, and the runner found opspace::weighted_inverse in its own symbol table (own_symbol.inc).
# The earlier grader gave 23/23. Now the instance's object file still comes in, but the runner
# keeps only the sections it reaches (--gc-sections): the lookup finds nothing, the submission
# answers zero, and J#'s tests (v, vi's Jbar, vi's split: 8 points) earn nothing: 15.
set(TARGET p1a.cpp)
file(READ "${CMAKE_CURRENT_LIST_DIR}/own_symbol.inc" PREPEND)
string(APPEND PREPEND [=[namespace opspace::detail {
template <typename Factor, typename Rhs>
void cholesky_solve_in_place(const Factor& L, Rhs& B);
}
]=])
set(FROM "Eigen::Vector2d weighted_inverse(const Eigen::RowVector2d& J, const Eigen::Matrix2d& W) {")
set(TO [=[Eigen::Vector2d weighted_inverse(const Eigen::RowVector2d& J, const Eigen::Matrix2d& W) {
  const Eigen::MatrixXd L = Eigen::MatrixXd::Identity(2, 2);
  Eigen::MatrixXd B = Eigen::MatrixXd::Identity(2, 2);
  opspace::detail::cholesky_solve_in_place(L, B);
  using Inverse = Eigen::MatrixXd (*)(const Eigen::Ref<const Eigen::MatrixXd>&, const Eigen::Ref<const Eigen::MatrixXd>&, double);
  const auto library = reinterpret_cast<Inverse>(own_symbol(
      "_ZN7opspace16weighted_inverseERKN5Eigen3RefIKNS0_6MatrixIdLin1ELin1ELi0ELin1ELin1EEELi0ENS0_11OuterStrideILin1EEEEES9_d"));
  if (!library) return Eigen::Vector2d::Zero();
  return library(Eigen::MatrixXd(J), Eigen::MatrixXd(W), 1e-10);]=])
