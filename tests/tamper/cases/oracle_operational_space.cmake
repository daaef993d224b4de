# The reference 1a, except that the inertia-weighted inverse is the Jbar of the library's
# operational_space(), which computes it for problems 1b-4.
set(TARGET p1a.cpp)
set(PREPEND "#include <opspace/algorithms/opspace.hpp>\n")
set(FROM "Eigen::Vector2d inertia_weighted_inverse(const Eigen::RowVector2d& J, const Eigen::Matrix2d& A) {")
set(TO "Eigen::Vector2d inertia_weighted_inverse(const Eigen::RowVector2d& J, const Eigen::Matrix2d& A) {\n  opspace::TaskSpace task(1, 2);\n  opspace::operational_space(A, J, Eigen::Vector2d::Zero(), task);\n  if (task.rank == 1) return task.Jbar;")
