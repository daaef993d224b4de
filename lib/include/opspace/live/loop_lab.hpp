/// @file live/loop_lab.hpp
/// The one Lab over any problem's scenario (scenarios/loop.hpp): its Loop, rebuilt from the
/// scenario's start by each reset, whose ticks are kept as the run's Result for its plots and
/// replay page. A problem's lab (problems/<key>/run/lab.hpp) adds only its own: what the page plots
/// and marks, the laws it switches, what it predicts of a push.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "opspace/live/lab.hpp"
#include "opspace/scenarios/loop.hpp"

namespace opspace::live {

/// A Lab over scenarios::Loop<Scenario>, recording its ResultOf<Scenario>.
template <class Scenario>
class LoopLab : public Lab {
 public:
  using Loop = scenarios::Loop<Scenario>;
  using Result = scenarios::ResultOf<Scenario>;

  const LabInfo& info() const override { return info_; }
  /// A new Loop from the scenario's start; the gains back to the goal's.
  void reset() override {
    loop_ = std::make_unique<Loop>(start_);
    result_ = Result{};
  }
  Simulation& simulation() override { return loop_->simulation(); }
  const Simulation& simulation() const override { return loop_->simulation(); }
  void set_law(int) override {}
  /// info().gains[gain] is kpx, kvx or kvj.
  void set_gain(int gain, double value) override {
    const std::string& name = info_.gains.at(gain).name;
    (name == "kpx" ? loop_->gains.kpx : name == "kvx" ? loop_->gains.kvx : loop_->gains.kvj) = value;
  }
  const Eigen::VectorXd& tick() override {
    result_.samples.push_back(loop_->tick());
    tau_ = result_.samples.back().tau;
    return tau_;
  }
  std::vector<std::string> csv_columns() const override { return loop_->scenario.csv_columns(); }
  std::vector<double> csv_row() const override { return loop_->scenario.csv_row(result_.samples.back()); }
  /// The samples of the current run (since the last reset): its plots and replay page.
  const Result& result() const { return result_; }
  /// The current run's scenario, with the law in force.
  const Scenario& scenario() const { return loop_->scenario; }

 protected:
  /// What the page shows, and the scenario every reset starts from; the problem's constructor
  /// then calls reset().
  LoopLab(LabInfo info, Scenario start) : info_(std::move(info)), start_(std::move(start)) {}

  LabInfo info_;                ///< what the page shows
  std::unique_ptr<Loop> loop_;  ///< the current run
  Result result_;               ///< its samples

 private:
  Scenario start_;
  Eigen::VectorXd tau_;
};

/// Markers of problems 2 and 3: the target x_pd and the tool x_p at the last tick, or the
/// first target twice before any tick.
template <class Result>
void target_and_tool(const Result& result, const Eigen::Vector3d& first_target,
                     std::vector<Eigen::Vector3d>& positions) {
  if (result.samples.empty()) {
    positions = {first_target, first_target};
    return;
  }
  const auto& s = result.samples.back();
  positions = {s.x_d.template head<3>(), s.x_p};
}

}  // namespace opspace::live
