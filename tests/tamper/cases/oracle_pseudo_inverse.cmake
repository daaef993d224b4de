# The reference 1a, except that pseudo_inverse calls the library's J+.
set(TARGET p1a.cpp)
set(PREPEND "#include <opspace/algorithms/linalg.hpp>\n")
set(FROM "Eigen::Vector2d pseudo_inverse(const Eigen::RowVector2d& J) {")
set(TO "Eigen::Vector2d pseudo_inverse(const Eigen::RowVector2d& J) {\n  if (J.size() == 2) return opspace::pseudo_inverse(J);")
