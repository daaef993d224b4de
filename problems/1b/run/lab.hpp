/// @file problems/1b/run/lab.hpp
/// Problem 1b live (docs/live.md): a LoopLab over its scenario (live/loop_lab.hpp) that adds
/// what is its own: what its page plots and marks, the laws it switches between, its gains' ranges.
/// It records its current run as the offline run's Result. `program` names the program serving
/// the page (its log's and the terminal's name, the page's heading).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "opspace/live/loop_lab.hpp"
#include <problems/1b/run/scenario.hpp>

namespace opspace::live {

/// Problem 1b: laws PART1, PART2, PART3. Unpushed, PART3's tip holds while PART2's wanders; a
/// push moves the tip under every law, by Jv A^-1 Je^T F / kpx at rest (problems/1b/run/offset.hpp).
/// Plots: tip error beside that prediction, q2 against q2_d.
class P1bLab final : public LoopLab<scenarios::p1b::Scenario> {
 public:
  P1bLab(const std::string& program, hw2::p1b::Part part, scenarios::p1b::Controller control);
  void set_law(int law) override;
  void set_push_torque(const Eigen::Ref<const Eigen::VectorXd>& torque) override;
  /// The page's ghost: path(part), the reference's tip path under `part` unpushed from t = 0,
  /// one point every `step` s (apps/: reference_runs.hpp).
  void set_reference(double step, const std::function<std::vector<Eigen::Vector3d>(hw2::p1b::Part)>& path);
  /// e = Jv A^-1 Je^T F / kpx for the last push torque and kpx (m): zero without a push.
  const Eigen::Vector3d& predicted_offset() const { return predicted_offset_; }
  void plot_values(std::vector<double>& values) const override;
  void marker_positions(std::vector<Eigen::Vector3d>& positions) const override;
  hw2::p1b::Part part() const { return loop_->scenario.part; }  ///< the law in force

 private:
  Eigen::Vector3d predicted_offset_ = Eigen::Vector3d::Zero();
};

}  // namespace opspace::live
