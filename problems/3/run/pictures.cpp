#include <problems/3/run/pictures.hpp>

#include <string>

#include "opspace/algorithms/euler_params.hpp"
#include "opspace/math/constants.hpp"
#include "opspace/model/urdf.hpp"
#include "opspace/visuals/visuals.hpp"

namespace opspace::scenarios::p3 {

namespace {

// One colour per quantity across every figure: measured blue, desired orange, average green.
constexpr const char* kMeasured = "#1f77b4";
constexpr const char* kDesired = "#ff7f0e";
constexpr const char* kAverage = "#2ca02c";
constexpr double kDegPerRad = 1.0 / kDeg;

using visuals::column;

/// The average of the last `window` values of `y` (fewer at the start).
std::vector<double> moving_average(const std::vector<double>& y, std::size_t window) {
  std::vector<double> out(y.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    sum += y[i];
    if (i >= window) sum -= y[i - window];
    out[i] = sum / static_cast<double>(i < window ? i + 1 : window);
  }
  return out;
}

}  // namespace

std::vector<plot::Figure> figures(const Result& result) {
  const std::vector<double> t = column(result, [](const Sample& s) { return s.t; });
  std::vector<plot::Figure> out;

  plot::Figure force{"force", "Contact force and moments the tool applies to the plane - problem 3"};
  const std::vector<double> fx = column(result, [](const Sample& s) { return s.tool_force.x(); });
  plot::Panel& f = force.panel("push along x", "F_x (N)");
  f.add("F_x (each 1 ms step)", t, fx).color = kMeasured;
  f.add("F_x, 10 ms average", t, moving_average(fx, 10)).color = kAverage;
  f.level("F_d = 10 N", kPushForce);
  plot::Panel& m = force.panel("moments about link7's origin", "N m");
  m.add("M_y", t, column(result, [](const Sample& s) { return s.tool_moment.y(); })).color = kMeasured;
  m.add("M_z", t, column(result, [](const Sample& s) { return s.tool_moment.z(); }), plot::Line::kDashed).color =
      kDesired;
  out.push_back(std::move(force));

  plot::Figure tracking{"tracking", "Motion directions against their goals - problem 3"};
  const char* axes[] = {"x", "y", "z"};
  for (int i = 1; i < 3; ++i) {
    plot::Panel& p = tracking.panel(std::string("link7 origin ") + axes[i], std::string(axes[i]) + " (m)");
    p.add(axes[i], t, column(result, [i](const Sample& s) { return s.x_p(i); })).color = kMeasured;
    p.add(std::string(axes[i]) + "_d", t, column(result, [i](const Sample& s) { return s.x_d(i); }),
          plot::Line::kDashed)
        .color = kDesired;
  }
  tracking.panel("rotation about x: error delta_phi_x", "deg")
      .add("delta_phi_x", t, column(result, [](const Sample& s) { return kDegPerRad * s.rotation_x_error; }))
      .color = kMeasured;
  out.push_back(std::move(tracking));

  plot::Figure tilt{"tilt", "Tool tilt against the plane (angle of link7's z axis from +x) - problem 3"};
  tilt.panel("tilt", "deg")
      .add("tilt", t, column(result, [](const Sample& s) { return kDegPerRad * s.tilt; }))
      .color = kMeasured;
  out.push_back(std::move(tilt));
  return out;
}

replay::Scene replay_scene(const Result& result) {
  replay::Scene scene;
  scene.title = "Problem 3, unified motion and force control";
  scene.subtitle = "KUKA iiwa: the tool pushes 10 N on the plane x = 0.05 while link7 tracks y_d, z_d and the "
                   "rotation about x";
  scene.model = load_urdf(robot_path(kRobotFile));
  scene.t = column(result, [](const Sample& s) { return s.t; });
  replay::Track face, push, origin, desired;
  for (const Sample& s : result.samples) {
    scene.q.emplace_back(s.q);
    // the centre of the tool face: 0.05 m ahead of link7's origin along its z axis
    face.push_back(s.x_p + 0.05 * rotation_matrix(s.lambda).col(2));
    push.push_back(s.tool_force);
    origin.push_back(s.x_p);
    desired.push_back(s.x_d.head<3>());  // x_d = 0: where the face meets the plane
  }
  // Look along the plane from beside the tool (+y), so that the push, along +x, is seen
  // side-on rather than through the plane.
  scene.view = Eigen::Vector3d(0.25, 1.0, 0.35);
  scene.markers.push_back(replay::Marker::plane("plane x = 0.05", "#95a5a6", Eigen::Vector3d(kPlaneX, 0.5, 0.65),
                                                -Eigen::Vector3d::UnitX(), 0.5));
  scene.markers.push_back(replay::Marker::arrow("push on the plane (1 cm per N)", "#e74c3c", face, push, 0.01));
  scene.markers.push_back(replay::Marker::point_at("desired x_d = (0, y_d, z_d)", "#ff7f0e", desired, 0.01));
  scene.markers.push_back(replay::Marker::trail("link7 origin", "#1f77b4", origin));
  scene.readouts.push_back({"F_x (N)", column(result, [](const Sample& s) { return s.tool_force.x(); })});
  scene.readouts.push_back({"tilt (deg)", column(result, [](const Sample& s) { return kDegPerRad * s.tilt; })});
  scene.readouts.push_back({"y, z error (mm)", column(result, [](const Sample& s) {
                              return 1e3 * (s.x_p.tail<2>() - s.x_d.segment<2>(1)).norm();
                            })});
  return scene;
}

}  // namespace opspace::scenarios::p3
