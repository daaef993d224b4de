# The reference 1a, except that J+ comes from the library, declared weak: the object file then
# refers to opspace::pseudo_inverse weakly ('w' in nm), and a weak reference pulls no library
# member into the link. The call of opspace::svd, allowed, pulled in the object file that held
# J+ too (linalg.cpp before the split): the grader that listed only the file's 'U'
# references gave 23/23. Now J+ is in no object file an allowed helper is in, the grader names
# the weak reference, and J+'s tests (iv and vi's split, 5 points) earn nothing: 18.
set(TARGET p1a.cpp)
set(PREPEND [=[#include <opspace/algorithms/linalg.hpp>
namespace opspace {
Eigen::MatrixXd pseudo_inverse(const Eigen::Ref<const Eigen::MatrixXd>& J, double tol) __attribute__((weak));
}
]=])
set(FROM "Eigen::Vector2d pseudo_inverse(const Eigen::RowVector2d& J) {")
set(TO [=[Eigen::Vector2d pseudo_inverse(const Eigen::RowVector2d& J) {
  const Eigen::MatrixXd Jm = J;
  (void)opspace::svd(Jm, 0);
  return opspace::pseudo_inverse(Jm, 1e-10);]=])
