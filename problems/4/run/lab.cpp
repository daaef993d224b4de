// Problem 4 live (problems/4/run/lab.hpp).
#include <Eigen/SVD>

#include <problems/4/run/lab.hpp>

namespace opspace::live {

namespace p4 = scenarios::p4;
using hw2::p4::Target;

namespace {

LabInfo page(const std::string& program, Target target) {
  LabInfo info;
  info.program = program;
  info.title = program + ": problem 4, the 3R arm " + p4::describe(target) + ", live";
  // What the run shows, measured ({K}: plot series K's latest value, docs/live.md), then what to try.
  info.subtitle = "now: distance to the target {0} mm, singular values of Jv {1}, {2}, {3} m; drag the arm into and "
                  "out of the singularity, switch to the plain law and compare";
  info.laws = {"your controller (question v)", "the plain operational-space controller"};
  const hw2::p4::Goal g = p4::goal(target);
  info.gains = {{"kpx", "kp, tip (1/s^2)", 10.0, 200.0, g.kpx},
                {"kvx", "kv, tip (1/s)", 2.0, 60.0, g.kvx},
                {"kvj", "kv, joints (1/s)", 0.0, 60.0, g.kvj}};
  info.plots = {{"distance to the target", "mm", {{"|x - x_d|", "#e74c3c"}}},
                {"singular values of Jv", "m", {{"sigma1", "#2c7be5"}, {"sigma2", "#27ae60"}, {"sigma3", "#e67e22"}}}};
  info.markers = {{"x_d", "target x_d", "#e74c3c", 0.02}, {"x", "tip x", "#2c7be5", 0.012}};
  return info;
}

}  // namespace

P4Lab::P4Lab(const std::string& program, Target target, p4::Controller control)
    : LoopLab(page(program, target), p4::Scenario(target, nullptr, "")), target_(target), control_(std::move(control)) {
  reset();
}

void P4Lab::reset() {
  plain_ = info_.law == 1;
  LoopLab::reset();
  use_law(loop_->scenario);
}

void P4Lab::use_law(p4::Scenario& scenario) const {
  if (plain_) {
    scenario.law = &p4::plain_control;
    scenario.who = "the plain controller";
    return;
  }
  const p4::Controller control = control_;
  const Target target = target_;
  scenario.law = [control, target](const hw2::p4::State& s, const TaskSpace&, const hw2::p4::Goal& g) {
    return control(target, s, g);
  };
  scenario.who = "your controller " + p4::describe(target_);
}

void P4Lab::set_law(int law) {
  plain_ = law == 1;
  use_law(loop_->scenario);  // on the running loop: no new world is built
}

void P4Lab::plot_values(std::vector<double>& values) const {
  const p4::Sample& s = result_.samples.back();
  const Eigen::Vector3d sigma = Eigen::JacobiSVD<Eigen::Matrix3d>(loop_->state().Jv).singularValues();
  values = {1000.0 * (s.x - loop_->scenario.goal().x_d).norm(), sigma(0), sigma(1), sigma(2)};
}

void P4Lab::marker_positions(std::vector<Eigen::Vector3d>& positions) const {
  const Eigen::Vector3d& x_d = loop_->scenario.goal().x_d;
  positions = {x_d, result_.samples.empty() ? x_d : result_.samples.back().x};
}

}  // namespace opspace::live
