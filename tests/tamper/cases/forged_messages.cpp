// Attack: forge the grader's channel. Writes lines in the old grader's result format and a
// well-formed answer header for a later request on every descriptor, then answers as a stub.
#include <problems/1a/contract.hpp>
#include <unistd.h>

#include <cstdint>
#include <cstring>

namespace opspace::hw2::p1a {

namespace {
void forge() {
  const char* line = "0 1000 0\n1 1000 0\n2 1000 0\n";
  const std::uint32_t header[4] = {0x5352534fu, 99, 0, 16};  // an answer to request 99
  for (int fd = 0; fd < 64; ++fd) {
    if (write(fd, line, std::strlen(line)) < 0) continue;
    if (write(fd, header, sizeof header) < 0) continue;
  }
}
}  // namespace

DegreesOfFreedom degrees_of_freedom() {
  forge();
  return {};
}
Eigen::Matrix2d mass_matrix(double, double) {
  forge();
  return Eigen::Matrix2d::Zero();
}
Eigen::RowVector2d task_jacobian() { return Eigen::RowVector2d::Zero(); }
Eigen::Vector2d pseudo_inverse(const Eigen::RowVector2d&) { return Eigen::Vector2d::Zero(); }
Eigen::Vector2d weighted_inverse(const Eigen::RowVector2d&, const Eigen::Matrix2d&) { return Eigen::Vector2d::Zero(); }
Eigen::Vector2d inertia_weighted_inverse(const Eigen::RowVector2d&, const Eigen::Matrix2d&) {
  return Eigen::Vector2d::Zero();
}
Eigen::Matrix2d nullspace_projector(const Eigen::RowVector2d&, const Eigen::Vector2d&) { return Eigen::Matrix2d::Zero(); }
Eigen::Vector2d inverse_kinematics_step(const Eigen::RowVector2d&, const Eigen::Vector2d&, double,
                                        const Eigen::Vector2d&) {
  return Eigen::Vector2d::Zero();
}
DisplacementSplit split_displacement(double, double, double) { return {}; }

}  // namespace opspace::hw2::p1a
