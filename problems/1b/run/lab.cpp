// Problem 1b live (problems/1b/run/lab.hpp).
#include <problems/1b/run/lab.hpp>
#include <problems/1b/run/offset.hpp>

namespace opspace::live {

namespace p1b = scenarios::p1b;
using hw2::p1b::Part;

namespace {

constexpr Part kLaws[] = {Part::kTipPd, Part::kPseudoInverseNullspace, Part::kDynamicallyConsistentNullspace};

// What the run shows, measured: {K} is the latest value of plot series K (docs/live.md), so the
// heading never promises what a student's controller may not do.
constexpr const char* kSubtitle =
    "now: tip error |x - x_d| = {0} mm (predicted for the push: {1} mm); joint 2 at q2 = {2} rad, its goal "
    "q2_d = {3} rad";
// What the page says of the physics (docs/live.md, "What a push does to the tip").
constexpr const char* kNote =
    "PART3's projector keeps the controller's own joint task from accelerating the tip: unpushed, a correct "
    "PART3 (the reference's) keeps its tip within a millimetre of x_d while joint 2 swings; PART2's wanders by "
    "centimetres to decimetres. "
    "A push is no controller torque: it reaches the tip as Jv A^-1 Je^T F, and the tip's PD holds it at the "
    "static offset Jv A^-1 Je^T F / kpx (orange, for the push of the moment; the tip follows it about "
    "kvx/kpx = 0.4 s late while the arm moves), undone when you let go. A stiffer kpx makes it smaller.";

int law_of(Part part) {
  for (int i = 0; i < 3; ++i) {
    if (kLaws[i] == part) return i;
  }
  return 2;
}

LabInfo page(const std::string& program, Part part) {
  LabInfo info;
  info.program = program;
  info.title = program + ": problem 1b on the PUMA 560, live";
  info.subtitle = kSubtitle;
  info.note = kNote;
  for (const Part p : kLaws) info.laws.push_back(p1b::describe(p));
  info.law = law_of(part);
  const hw2::p1b::Goal g = p1b::goal(0.0, p1b::initial_q());
  // Ranges that keep the run stable: the tip PD is critically damped at kvx = 2 sqrt(kpx).
  info.gains = {{"kpx", "kp, tip (1/s^2)", 10.0, 200.0, g.kpx},
                {"kvx", "kv, tip (1/s)", 2.0, 60.0, g.kvx},
                {"kvj", "kv, joints (1/s)", 0.0, 60.0, g.kvj}};
  info.plots = {{"tip error", "mm",
                 {{"measured |x - x_d|", "#e74c3c"}, {"predicted |Jv A^-1 Je^T F| / kpx", "#e67e22"}}},
                {"joint 2", "rad", {{"q2", "#2c7be5"}, {"q2_d", "#7f8c8d"}}}};
  info.markers = {{"x_d", "target x_d", "#e74c3c", 0.02}, {"x", "tip x", "#2c7be5", 0.012}};
  return info;
}

}  // namespace

P1bLab::P1bLab(const std::string& program, Part part, p1b::Controller control)
    : LoopLab(page(program, part), p1b::Scenario(kLaws[law_of(part)], std::move(control))) {
  reset();
}

void P1bLab::set_law(int law) { loop_->scenario.part = kLaws[law]; }

void P1bLab::set_push_torque(const Eigen::Ref<const Eigen::VectorXd>& torque) {
  if (torque.isZero(0.0)) {
    predicted_offset_.setZero();
    return;
  }
  const hw2::p1b::State& s = loop_->state();
  hw2::p1b::Goal g = p1b::goal(s.t, s.q);
  loop_->gains.apply(g);  // the kpx of this tick
  predicted_offset_ = p1b_static_tip_offset(s, torque, g.kpx);
}

void P1bLab::set_reference(double step, const std::function<std::vector<Eigen::Vector3d>(Part)>& path) {
  info_.ghost = Ghost{"reference tip (solutions/, this law, unpushed)", "#8e44ad", step, {}};
  for (const Part p : kLaws) info_.ghost.paths.push_back(path(p));
}

void P1bLab::plot_values(std::vector<double>& values) const {
  const p1b::Sample& s = result_.samples.back();
  const Eigen::Vector3d& x_d = loop_->scenario.x_d();
  values = {1000.0 * (s.x - x_d).norm(), 1000.0 * predicted_offset_.norm(), s.q(1), s.q2_desired};
}

void P1bLab::marker_positions(std::vector<Eigen::Vector3d>& positions) const {
  const Eigen::Vector3d& x_d = loop_->scenario.x_d();
  positions = {x_d, result_.samples.empty() ? x_d : result_.samples.back().x};
}

}  // namespace opspace::live
