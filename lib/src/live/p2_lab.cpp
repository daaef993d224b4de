// Problem 2 live (live/labs.hpp).
#include <algorithm>
#include <cmath>

#include "opspace/live/labs.hpp"

namespace opspace::live {

namespace p2 = scenarios::p2;

P2Lab::P2Lab(p2::Controller control, p2::DesiredAcceleration desired_acceleration)
    : control_(std::move(control)), desired_acceleration_(std::move(desired_acceleration)) {
  info_.program = "hw2-p2";
  info_.title = "hw2-p2: problem 2 on the KUKA iiwa, live";
  info_.subtitle = "push the elbow while the tool tracks: the task holds, the null space gives";
  info_.laws = {"decoupled PD + feed-forward + null-space damping + gravity compensation"};
  const hw2::p2::Goal g = p2::goal(0.0);
  info_.gains = {{"kpx", "kp, task (1/s^2)", 10.0, 200.0, g.kpx},
                 {"kvx", "kv, task (1/s)", 2.0, 60.0, g.kvx},
                 {"kvj", "kv, joints (1/s)", 0.0, 60.0, g.kvj}};
  info_.plots = {{"position error", "mm", {{"|x_p - x_pd|", "#e74c3c"}}},
                 {"orientation error", "deg", {{"angle of R R_d^T", "#8e44ad"}}}};
  info_.markers = {{"x_d", "target x_pd", "#e74c3c", 0.02}, {"x", "link7 x_p", "#2c7be5", 0.012}};
  reset();
}

std::unique_ptr<p2::Loop> P2Lab::make_loop() const {
  return std::make_unique<p2::Loop>(control_, desired_acceleration_);
}

void P2Lab::plot_values(std::vector<double>& values) const {
  const p2::Sample& s = result_.samples.back();
  // The angle between two orientations: 2 acos |lambda . lambda_d| (unit Euler parameters).
  const double dot = std::min(1.0, std::abs(s.lambda.dot(s.x_d.tail<4>())));
  values = {1000.0 * (s.x_p - s.x_d.head<3>()).norm(), 2.0 * std::acos(dot) * 180.0 / 3.14159265358979323846};
}

void P2Lab::marker_positions(std::vector<Eigen::Vector3d>& positions) const {
  target_and_tool(result_, p2::goal(0.0).x_d.head<3>(), positions);
}

}  // namespace opspace::live
