# The reference 1a, except that J+ comes from the library by its mangled name in inline
# assembly: a weak reference in a data word of the file's own, which the C++ reads as a function
# pointer; the call of opspace::require_finite, allowed, pulled in the object file that held J+
# too (before the split). The earlier grader gave 23/23. Now the grader names the reference and
# J+'s tests (iv and vi's split, 5 points) earn nothing: 18.
set(TARGET p1a.cpp)
set(PREPEND [=[#include <opspace/algorithms/linalg.hpp>
asm(".weak _ZN7opspace14pseudo_inverseERKN5Eigen3RefIKNS0_6MatrixIdLin1ELin1ELi0ELin1ELin1EEELi0ENS0_11OuterStrideILin1EEEEEd\n"
    ".pushsection .data.rel.ro.library_pinv,\"aw\"\n"
    ".p2align 3\n"
    "library_pinv_address:\n"
    ".quad _ZN7opspace14pseudo_inverseERKN5Eigen3RefIKNS0_6MatrixIdLin1ELin1ELi0ELin1ELin1EEELi0ENS0_11OuterStrideILin1EEEEEd\n"
    ".popsection\n");
extern "C" const void* const library_pinv_address;
]=])
set(FROM "Eigen::Vector2d pseudo_inverse(const Eigen::RowVector2d& J) {")
set(TO [=[Eigen::Vector2d pseudo_inverse(const Eigen::RowVector2d& J) {
  opspace::require_finite(Eigen::MatrixXd(J), "J");
  using Inverse = Eigen::MatrixXd (*)(const Eigen::Ref<const Eigen::MatrixXd>&, double);
  return reinterpret_cast<Inverse>(library_pinv_address)(Eigen::MatrixXd(J), 1e-10);]=])
