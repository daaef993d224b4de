# The reference 1a, except that mass_matrix ends the program: only the mass-matrix test is lost.
set(TARGET p1a.cpp)
set(PREPEND "#include <cstdlib>\n")
set(FROM "Eigen::Matrix2d mass_matrix(double m1, double m2) {")
set(TO "Eigen::Matrix2d mass_matrix(double m1, double m2) {\n  std::exit(0);")
