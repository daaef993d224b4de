// Problem 2 live (problems/2/run/lab.hpp).
#include <algorithm>
#include <cmath>

#include <problems/2/run/lab.hpp>
#include "opspace/math/constants.hpp"

namespace opspace::live {

namespace p2 = scenarios::p2;

namespace {

LabInfo page(const std::string& program) {
  LabInfo info;
  info.program = program;
  info.title = program + ": problem 2 on the KUKA iiwa, live";
  // What the run shows, measured ({K}: plot series K's latest value, docs/live.md): no promise.
  info.subtitle = "now: position error |x_p - x_pd| = {0} mm, orientation error {1} deg; push the elbow and watch both";
  info.laws = {"decoupled PD + feed-forward + null-space damping + gravity compensation"};
  const hw2::p2::Goal g = p2::goal(0.0);
  info.gains = {{"kpx", "kp, task (1/s^2)", 10.0, 200.0, g.kpx},
                {"kvx", "kv, task (1/s)", 2.0, 60.0, g.kvx},
                {"kvj", "kv, joints (1/s)", 0.0, 60.0, g.kvj}};
  info.plots = {{"position error", "mm", {{"|x_p - x_pd|", "#e74c3c"}}},
                {"orientation error", "deg", {{"angle of R R_d^T", "#8e44ad"}}}};
  info.markers = {{"x_d", "target x_pd", "#e74c3c", 0.02}, {"x", "link7 x_p", "#2c7be5", 0.012}};
  return info;
}

}  // namespace

P2Lab::P2Lab(const std::string& program, p2::Controller control, p2::DesiredAcceleration desired_acceleration)
    : LoopLab(page(program), p2::Scenario{std::move(control), std::move(desired_acceleration)}) {
  reset();
}

void P2Lab::plot_values(std::vector<double>& values) const {
  const p2::Sample& s = result_.samples.back();
  // The angle between two orientations: 2 acos |lambda . lambda_d| (unit Euler parameters).
  const double dot = std::min(1.0, std::abs(s.lambda.dot(s.x_d.tail<4>())));
  values = {1000.0 * (s.x_p - s.x_d.head<3>()).norm(), 2.0 * std::acos(dot) * 180.0 / kPi};
}

void P2Lab::marker_positions(std::vector<Eigen::Vector3d>& positions) const {
  target_and_tool(result_, p2::goal(0.0).x_d.head<3>(), positions);
}

}  // namespace opspace::live
