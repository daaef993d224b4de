// Problem 1c live (problems/1c/run/lab.hpp).
#include <problems/1c/run/lab.hpp>

#include <utility>

namespace opspace::live {

namespace p1b = scenarios::p1b;

namespace {

// What the run shows, measured: {K} is the latest value of plot series K (docs/live.md).
constexpr const char* kSubtitle = "now: tip error |x - x_d| = {0} mm; the fastest joint turns at {1} rad/s";
constexpr const char* kNote =
    "The tip PD acts in the task space only: nothing damps the arm's motion in the null space of Jv. "
    "A push sets the joints moving, and they keep moving after you let go; their Coriolis and centrifugal "
    "forces reach the tip, which wanders by centimetres. Problem 1b's PART1 adds A (-kvj dq), which "
    "takes that motion out.";

LabInfo page(const std::string& program) {
  LabInfo info;
  info.program = program;
  info.title = program + ": problem 1c on the PUMA 560, live";
  info.subtitle = kSubtitle;
  info.note = kNote;
  info.laws = {"tip PD without joint damping"};
  info.law = 0;
  const hw2::p1b::Goal g = p1b::goal(0.0, p1b::initial_q());
  // Ranges that keep the run stable: the tip PD is critically damped at kvx = 2 sqrt(kpx).
  info.gains = {{"kpx", "kp, tip (1/s^2)", 10.0, 200.0, g.kpx}, {"kvx", "kv, tip (1/s)", 2.0, 60.0, g.kvx}};
  info.plots = {{"tip error", "mm", {{"measured |x - x_d|", "#e74c3c"}}},
                {"fastest joint", "rad/s", {{"max |dq_i|", "#2c7be5"}}}};
  info.markers = {{"x_d", "target x_d", "#e74c3c", 0.02}, {"x", "tip x", "#2c7be5", 0.012}};
  return info;
}

}  // namespace

P1cLab::P1cLab(const std::string& program, scenarios::p1c::Controller control)
    : LoopLab(page(program), scenarios::p1c::scenario(std::move(control))) {
  reset();
}

void P1cLab::plot_values(std::vector<double>& values) const {
  const p1b::Sample& s = result_.samples.back();
  double speed = 0.0;
  if (result_.samples.size() > 1) {
    const p1b::Sample& before = result_.samples[result_.samples.size() - 2];
    speed = (s.q - before.q).cwiseAbs().maxCoeff() / (s.t - before.t);
  }
  values = {1000.0 * (s.x - loop_->scenario.x_d()).norm(), speed};
}

void P1cLab::marker_positions(std::vector<Eigen::Vector3d>& positions) const {
  const Eigen::Vector3d& x_d = loop_->scenario.x_d();
  positions = {x_d, result_.samples.empty() ? x_d : result_.samples.back().x};
}

}  // namespace opspace::live
