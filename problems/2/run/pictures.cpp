#include <algorithm>
#include <cmath>
#include <string>

#include <problems/2/run/pictures.hpp>
#include "opspace/model/urdf.hpp"
#include "opspace/visuals/visuals.hpp"

namespace opspace::scenarios::p2 {

namespace {

constexpr const char* kMeasured = "#1f77b4";
constexpr const char* kDesired = "#ff7f0e";
constexpr const char* kWho = "problem 2, iiwa tracking";

using visuals::column;

// position_error(): the graded tests' series (scenario.hpp), so the plot is what they read.
// The angle of R R_d^T from the Euler parameters: 2 acos |lambda . lambda_d|.
double orientation_error(const Sample& s) {
  const double c = std::min(1.0, std::abs(s.lambda.dot(s.x_d.tail<4>())));
  return 2.0 * std::acos(c);
}

}  // namespace

std::vector<plot::Figure> figures(const Result& result) {
  const std::vector<double> t = column(result, [](const Sample& s) { return s.t; });
  std::vector<plot::Figure> out;

  plot::Figure position{"position", std::string("Position of link7's origin against x_d(t) - ") + kWho};
  const char* axes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    plot::Panel& p = position.panel(axes[i], std::string(axes[i]) + " (m)");
    p.add(axes[i], t, column(result, [i](const Sample& s) { return s.x_p(i); })).color = kMeasured;
    p.add(std::string(axes[i]) + "_d", t, column(result, [i](const Sample& s) { return s.x_d(i); }),
          plot::Line::kDashed)
        .color = kDesired;
  }
  out.push_back(std::move(position));

  plot::Figure error{"error", std::string("Tracking errors - ") + kWho};
  error.panel("position error |x_p - x_pd|", "mm")
      .add("|x_p - x_pd|", t, column(result, [](const Sample& s) { return 1e3 * position_error(s); }))
      .color = kMeasured;
  error.panel("orientation error: angle of R R_d^T", "mrad")
      .add("angle", t, column(result, [](const Sample& s) { return 1e3 * orientation_error(s); }))
      .color = kMeasured;
  out.push_back(std::move(error));

  plot::Figure lambda{"lambda", std::string("Euler parameters against lambda_d(t) - ") + kWho};
  for (int i = 0; i < 4; ++i) {
    const std::string name = "lambda_" + std::to_string(i);
    plot::Panel& p = lambda.panel(name, "");
    p.add(name, t, column(result, [i](const Sample& s) { return s.lambda(i); })).color = kMeasured;
    p.add(name + "_d", t, column(result, [i](const Sample& s) { return s.x_d(3 + i); }), plot::Line::kDashed)
        .color = kDesired;
  }
  lambda.columns = 2;
  out.push_back(std::move(lambda));

  out.push_back(visuals::torque_figure(load_urdf(robot_path(kRobotFile)), t, visuals::torques(result), kWho));
  return out;
}

replay::Scene replay_scene(const Result& result) {
  replay::Scene scene;
  scene.title = "Problem 2: position and Euler-parameter tracking";
  scene.subtitle = "KUKA iiwa: link7's origin should follow the moving target x_d(t)";
  scene.model = load_urdf(robot_path(kRobotFile));
  replay::Track target, path;
  for (const Sample& s : result.samples) {
    scene.t.push_back(s.t);
    scene.q.emplace_back(s.q);
    target.push_back(s.x_d.head<3>());
    path.push_back(s.x_p);
  }
  scene.view = Eigen::Vector3d(1.0, 0.6, 0.5);
  scene.markers.push_back(replay::Marker::point_at("desired x_d(t)", "#e74c3c", target, 0.02));
  scene.markers.push_back(replay::Marker::trail("path of link7's origin", "#1f77b4", path));
  scene.readouts.push_back({"position error (mm)", column(result, [](const Sample& s) { return 1e3 * position_error(s); })});
  scene.readouts.push_back(
      {"orientation error (mrad)", column(result, [](const Sample& s) { return 1e3 * orientation_error(s); })});
  return scene;
}

}  // namespace opspace::scenarios::p2
