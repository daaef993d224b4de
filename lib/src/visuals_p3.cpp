#include "opspace/scenarios/p3_visuals.hpp"

#include <string>

namespace opspace::scenarios::p3 {

namespace {

// One colour per quantity across every figure: measured blue, desired orange, average green.
constexpr const char* kMeasured = "#1f77b4";
constexpr const char* kDesired = "#ff7f0e";
constexpr const char* kAverage = "#2ca02c";
constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;

/// The column `f(sample)` of every sample.
template <class F>
std::vector<double> column(const Result& r, F f) {
  std::vector<double> out;
  out.reserve(r.samples.size());
  for (const Sample& s : r.samples) out.push_back(f(s));
  return out;
}

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

}  // namespace opspace::scenarios::p3
