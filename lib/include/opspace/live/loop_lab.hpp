/// @file live/loop_lab.hpp
/// What the four problems' Labs share: a scenario's Loop (scenarios/p*.hpp), rebuilt by each
/// reset, whose ticks are kept as the run's Result for its plots and replay page.
#pragma once

#include <memory>
#include <vector>

#include "opspace/live/lab.hpp"

namespace opspace::live {

/// A Lab over a scenario's `Loop` (tick(), simulation(), gains) recording a `Result`.
template <class Loop, class Result>
class LoopLab : public Lab {
 public:
  const LabInfo& info() const override { return info_; }
  void reset() override {
    loop_ = make_loop();
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
  /// The samples of the current run (since the last reset): its plots and replay page.
  const Result& result() const { return result_; }

 protected:
  /// The scenario's loop at its start, with the law in force.
  virtual std::unique_ptr<Loop> make_loop() const = 0;

  LabInfo info_;               ///< set by the problem's constructor, which then calls reset()
  std::unique_ptr<Loop> loop_;  ///< the current run
  Result result_;               ///< its samples

 private:
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
