#include <problems/1b/run/pictures.hpp>

#include <string>

#include "opspace/model/urdf.hpp"
#include "opspace/visuals/visuals.hpp"

namespace opspace::scenarios::p1b {

namespace {

using hw2::p1b::Part;

// One colour per quantity across every figure: measured blue, desired orange, limits red.
constexpr const char* kMeasured = "#1f77b4";
constexpr const char* kDesired = "#ff7f0e";
constexpr const char* kPart2 = "#d62728";
constexpr const char* kPart3 = "#2ca02c";

using visuals::column;

std::vector<double> times(const Result& r) {
  return column(r, [](const Sample& s) { return s.t; });
}

Eigen::Vector3d desired_tip() { return goal(0.0, initial_q()).x_d; }

std::vector<double> tip_error_mm(const Result& r) {
  const Eigen::Vector3d x_d = desired_tip();
  return column(r, [&](const Sample& s) { return 1e3 * (s.x - x_d).norm(); });
}

std::string short_name(Part part) {
  const std::string d = describe(part);
  return d.substr(0, d.find(':'));
}

}  // namespace

std::vector<plot::Figure> figures(const Result& result, Part part) {
  const std::vector<double> t = times(result);
  const Eigen::Vector3d x_d = desired_tip();
  const std::string who = describe(part);
  std::vector<plot::Figure> out;

  plot::Figure tip{"tip", "Tip position against its target x_d - " + who};
  const char* axes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    plot::Panel& p = tip.panel(std::string("tip ") + axes[i], std::string(axes[i]) + " (m)");
    p.add(std::string(axes[i]), t, column(result, [i](const Sample& s) { return s.x(i); })).color = kMeasured;
    p.add(std::string(axes[i]) + "_d", t, std::vector<double>(t.size(), x_d(i)), plot::Line::kDashed).color = kDesired;
  }
  out.push_back(std::move(tip));

  plot::Figure error{"error", "Tracking errors - " + who};
  error.panel("tip error |x - x_d|", "mm").add("|x - x_d|", t, tip_error_mm(result)).color = kMeasured;
  if (part == Part::kPseudoInverseNullspace || part == Part::kDynamicallyConsistentNullspace) {
    error.panel("joint 2 error q2 - q2_d", "rad")
        .add("q2 - q2_d", t, column(result, [](const Sample& s) { return s.q(1) - s.q2_desired; }))
        .color = kMeasured;
  }
  out.push_back(std::move(error));

  if (part == Part::kPseudoInverseNullspace || part == Part::kDynamicallyConsistentNullspace) {
    plot::Figure q2{"q2", "Joint 2 (shoulder pitch) against its null-space goal q2_d - " + who};
    plot::Panel& p = q2.panel("joint 2", "rad");
    p.add("q2", t, column(result, [](const Sample& s) { return s.q(1); })).color = kMeasured;
    p.add("q2_d", t, column(result, [](const Sample& s) { return s.q2_desired; }), plot::Line::kDashed).color =
        kDesired;
    out.push_back(std::move(q2));
  }

  out.push_back(visuals::torque_figure(load_urdf(robot_path(kRobotFile)), t, visuals::torques(result), who));
  return out;
}

replay::Scene replay_scene(const Result& result, Part part) {
  replay::Scene scene;
  scene.title = "Problem 1b, " + describe(part);
  scene.subtitle = "PUMA 560: the tip should hold x_d while joint 2 follows q2_d in the null space";
  scene.model = load_urdf(robot_path(kRobotFile));
  scene.t = times(result);
  replay::Track tip;
  for (const Sample& s : result.samples) {
    scene.q.emplace_back(s.q);
    tip.push_back(s.x);
  }
  // The arm swings in the base's y-z plane (q1 = 90 deg): look at it from the side (+x).
  scene.view = Eigen::Vector3d(1.0, 0.3, 0.35);
  scene.markers.push_back(replay::Marker::point_at("desired tip x_d", "#e74c3c", {desired_tip()}, 0.02));
  scene.markers.push_back(replay::Marker::trail("tip path", "#1f77b4", tip));
  scene.readouts.push_back({"tip error (mm)", tip_error_mm(result)});
  scene.readouts.push_back({"q2 (rad)", column(result, [](const Sample& s) { return s.q(1); })});
  scene.readouts.push_back({"q2_d (rad)", column(result, [](const Sample& s) { return s.q2_desired; })});
  return scene;
}

plot::Figure compare_figure(const Result& part2, const Result& part3) {
  plot::Figure f{"drift", "Problem 1b: the same null-space goal, two projectors"};
  plot::Panel& tip = f.panel("tip drift |x - x_d| (log scale): only the dynamically consistent projector holds the tip",
                             "mm");
  tip.log_y = true;
  tip.add(short_name(Part::kPseudoInverseNullspace) + " (pseudo-inverse)", times(part2), tip_error_mm(part2)).color =
      kPart2;
  tip.add(short_name(Part::kDynamicallyConsistentNullspace) + " (dyn. consistent)", times(part3), tip_error_mm(part3))
      .color = kPart3;
  plot::Panel& q2 = f.panel("joint 2 against q2_d", "rad");
  q2.add("PART2 q2", times(part2), column(part2, [](const Sample& s) { return s.q(1); })).color = kPart2;
  q2.add("PART3 q2", times(part3), column(part3, [](const Sample& s) { return s.q(1); })).color = kPart3;
  q2.add("q2_d", times(part3), column(part3, [](const Sample& s) { return s.q2_desired; }), plot::Line::kDashed)
      .color = kDesired;
  return f;
}

}  // namespace opspace::scenarios::p1b
