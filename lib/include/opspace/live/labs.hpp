/// @file live/labs.hpp
/// The four problems live (docs/live.md): each a LoopLab over its scenario (live/loop_lab.hpp)
/// that adds what is its own: what its page plots and marks, the laws it switches between, its
/// gains' ranges. Each records its current run as the offline run's Result. `program` names the
/// program serving the page (its log's and the terminal's name, the page's heading).
#pragma once

#include <functional>
#include <string>

#include "opspace/live/loop_lab.hpp"
#include <problems/1b/scenario.hpp>
#include <problems/2/scenario.hpp>
#include <problems/3/scenario.hpp>
#include <problems/4/scenario.hpp>

namespace opspace::live {

/// Problem 1b: laws PART1, PART2, PART3. Unpushed, PART3's tip holds while PART2's wanders; a
/// push moves the tip under every law, by Jv A^-1 Je^T F / kpx at rest (live/p1b_offset.hpp).
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

/// Problem 2: the iiwa tracks its trajectory; push the elbow while it tracks. Plots: position
/// and orientation error.
class P2Lab final : public LoopLab<scenarios::p2::Scenario> {
 public:
  P2Lab(const std::string& program, scenarios::p2::Controller control,
        scenarios::p2::DesiredAcceleration desired_acceleration);
  void plot_values(std::vector<double>& values) const override;
  void marker_positions(std::vector<Eigen::Vector3d>& positions) const override;
};

/// Problem 3: the tool pushes 10 N on the plane; pull it off and let it come back. Plots: F_x
/// with its 10 ms mean against 10 N, the tool's tilt.
class P3Lab final : public LoopLab<scenarios::p3::Scenario> {
 public:
  P3Lab(const std::string& program, scenarios::p3::Controller control);
  void plot_values(std::vector<double>& values) const override;
  void marker_positions(std::vector<Eigen::Vector3d>& positions) const override;
};

/// Problem 4, question v toward `target`: the student's law against the plain one; drag the arm
/// into and out of the singularity. Plots: distance to the target, the singular values of Jv.
class P4Lab final : public LoopLab<scenarios::p4::Scenario> {
 public:
  P4Lab(const std::string& program, hw2::p4::Target target, scenarios::p4::Controller control);
  void reset() override;
  void set_law(int law) override;
  void plot_values(std::vector<double>& values) const override;
  void marker_positions(std::vector<Eigen::Vector3d>& positions) const override;
  bool plain() const { return plain_; }  ///< the plain law is in force

 private:
  void use_law(scenarios::p4::Scenario& scenario) const;  // the law plain_ names, and its name in errors
  hw2::p4::Target target_;
  scenarios::p4::Controller control_;
  bool plain_ = false;
};

}  // namespace opspace::live
