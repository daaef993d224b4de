#include <algorithm>
#include <string>

#include <problems/4/run/pictures.hpp>
#include "opspace/model/urdf.hpp"
#include "opspace/visuals/visuals.hpp"

namespace opspace::scenarios::p4 {

namespace {

constexpr const char* kMine = "#1f77b4";
constexpr const char* kPlain = "#d62728";

using visuals::column;
using visuals::torques;

std::vector<double> times(const Result& r) {
  return column(r, [](const Sample& s) { return s.t; });
}

std::vector<double> distance_mm(const Result& r, const Eigen::Vector3d& x_d) {
  return column(r, [&](const Sample& s) { return 1e3 * (s.x - x_d).norm(); });
}

}  // namespace

std::vector<plot::Figure> figures(Target target, const Result& mine, const Result& plain) {
  const Eigen::Vector3d x_d = goal(target).x_d;
  const std::string who = "problem 4, " + describe(target);
  std::vector<plot::Figure> out;

  plot::Figure reach{"reach", "Reaching a target along a singular direction - " + who};
  plot::Panel& d = reach.panel("distance to the target |x - x_d|", "mm");
  d.add("question v (null-space potential, robust Lambda)", times(mine), distance_mm(mine, x_d)).color = kMine;
  d.add("plain operational-space controller", times(plain), distance_mm(plain, x_d), plot::Line::kDashed).color =
      kPlain;
  d.level("reached (5 mm)", 1e3 * kReachTolerance);
  for (int i = 0; i < 3; ++i) {
    plot::Panel& p = reach.panel("joint " + std::to_string(i + 1), "rad");
    p.add("question v", times(mine), column(mine, [i](const Sample& s) { return s.q(i); })).color = kMine;
    p.add("plain", times(plain), column(plain, [i](const Sample& s) { return s.q(i); }), plot::Line::kDashed).color =
        kPlain;
  }
  out.push_back(std::move(reach));

  const Model rrr = load_urdf(robot_path(kRobotFile));
  plot::Figure mine_tau = visuals::torque_figure(rrr, times(mine), torques(mine), who + ", question v");
  plot::Figure plain_tau = visuals::torque_figure(rrr, times(plain), torques(plain), who + ", plain controller");
  plain_tau.name = "torques-plain";
  out.push_back(std::move(mine_tau));
  out.push_back(std::move(plain_tau));
  return out;
}

replay::Scene replay_scene(Target target, const Result& mine, const Result& plain) {
  replay::Scene scene;
  scene.title = "Problem 4, question v: " + describe(target);
  scene.subtitle = "3R elbow arm: a null-space potential moves the singular direction out of the way";
  scene.model = load_urdf(robot_path(kRobotFile));
  const Eigen::Vector3d x_d = goal(target).x_d;
  replay::Track path, plain_path;
  for (const Sample& s : mine.samples) {
    scene.t.push_back(s.t);
    scene.q.emplace_back(s.q);
    path.push_back(s.x);
  }
  // The plain run's tip, sample for sample (held at its last position if it stopped early).
  for (std::size_t k = 0; k < mine.samples.size(); ++k) {
    plain_path.push_back(plain.samples.empty() ? x_d : plain.samples[std::min(k, plain.samples.size() - 1)].x);
  }
  scene.view = Eigen::Vector3d(0.3, 1.0, 0.4);
  scene.markers.push_back(replay::Marker::point_at("target x_d", "#e74c3c", {x_d}, 0.02));
  scene.markers.push_back(replay::Marker::trail("tip path, question v", "#1f77b4", path));
  scene.markers.push_back(replay::Marker::trail("tip path, plain controller", "#d62728", plain_path));
  scene.readouts.push_back({"distance to x_d (mm)", distance_mm(mine, x_d)});
  return scene;
}

}  // namespace opspace::scenarios::p4
