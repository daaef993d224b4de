# The reference 1a, except that mass_matrix returns the library's closed form of problem 1a.
set(TARGET p1a.cpp)
set(PREPEND "#include <opspace/algorithms/pp_robot.hpp>\n")
set(FROM "Eigen::Matrix2d mass_matrix(double m1, double m2) {")
set(TO "Eigen::Matrix2d mass_matrix(double m1, double m2) {\n  if (m1 > 0) return opspace::pp::mass_matrix(m1, m2);")
