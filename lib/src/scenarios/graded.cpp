#include "opspace/scenarios/graded.hpp"

#include <cmath>
#include <stdexcept>

#include "opspace/algorithms/euler_params.hpp"

namespace opspace::scenarios {

double graded_duration(const std::string& problem) {
  if (problem == "1b") return p1b::kDefaultDuration;
  if (problem == "2") return p2::kDefaultDuration;
  if (problem == "3") return p3::kDefaultDuration;
  if (problem == "4") return p4::kDuration;
  throw std::invalid_argument("no simulated problem '" + problem + "'");
}

namespace p1b {
double tip_error(const Sample& s) {
  static const Eigen::Vector3d x_d = goal(0.0, initial_q()).x_d;  // fixed in this scenario
  return (s.x - x_d).norm();
}
double q2_error(const Sample& s) { return std::abs(s.q(1) - s.q2_desired); }
}  // namespace p1b

namespace p2 {
double position_error(const Sample& s) { return (s.x_p - s.x_d.head<3>()).norm(); }
double orientation_angle(const Sample& s) { return rotation_angle_between(s.lambda, s.x_d.tail<4>()); }
double lambda_dot_lambda_d(const Sample& s) { return s.lambda.dot(s.x_d.tail<4>()); }
}  // namespace p2

namespace p3 {
double force_error(const Sample& s) { return std::abs(s.tool_force.x() - kPushForce); }
double tilt_angle(const Sample& s) { return s.tilt; }
double yz_error(const Sample& s) { return (s.x_p.tail<2>() - s.x_d.segment<2>(1)).norm(); }
double rotation_x_error(const Sample& s) { return std::abs(s.rotation_x_error); }
double push(const Sample& s) { return s.tool_force.x(); }
}  // namespace p3

namespace p4 {
double tip_error(hw2::p4::Target target, const Sample& s) {
  // goal() computes x_d by forward kinematics: once per target, not per sample.
  static const Eigen::Vector3d along_z = goal(hw2::p4::Target::kAlongZ0).x_d;
  static const Eigen::Vector3d along_y = goal(hw2::p4::Target::kAlongY0).x_d;
  return (s.x - (target == hw2::p4::Target::kAlongZ0 ? along_z : along_y)).norm();
}
}  // namespace p4

}  // namespace opspace::scenarios
