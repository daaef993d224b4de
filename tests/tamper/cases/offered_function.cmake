# The reference 1b, except that PART2 uses opspace::pseudo_inverse, which the stub offers.
set(TARGET p1b.cpp)
set(PREPEND "#include <opspace/algorithms/linalg.hpp>\n")
set(FROM "const Matrix63d Jv_pinv = s.Jv.transpose() * (s.Jv * s.Jv.transpose()).inverse();")
set(TO "const Matrix63d Jv_pinv = opspace::pseudo_inverse(s.Jv);")
