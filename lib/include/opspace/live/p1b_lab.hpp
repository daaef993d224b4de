/// @file live/p1b_lab.hpp
/// Problem 1b live (docs/live.md): the PUMA holds its tip while joint 2 follows q2_d(t) in the
/// null space; push the elbow under PART2 and the tip wanders, under PART3 it holds.
#pragma once

#include "opspace/live/lab.hpp"
#include "opspace/scenarios/p1b.hpp"

namespace opspace::live {

/// Problem 1b's Lab: laws PART1, PART2, PART3 (info().laws in that order); gains kpx, kvx, kvj.
class P1bLab final : public Lab {
 public:
  /// Starts at law `part` (PART1..3) with `control`, the student's or the reference's.
  P1bLab(hw2::p1b::Part part, scenarios::p1b::Controller control);
  const LabInfo& info() const override { return info_; }
  void reset() override;
  Simulation& simulation() override { return loop_->simulation(); }
  void set_law(int law) override;
  void set_gain(int gain, double value) override;
  const Eigen::VectorXd& tick() override;
  void plot_values(std::vector<double>& values) const override;
  void marker_positions(std::vector<Eigen::Vector3d>& positions) const override;
  std::vector<std::string> csv_columns() const override { return scenarios::p1b::csv_columns(); }
  std::vector<double> csv_row() const override;
  /// The samples of the current run (since the last reset): its plots and replay page.
  const scenarios::p1b::Result& result() const { return result_; }
  /// The law in force.
  hw2::p1b::Part part() const { return loop_->part; }

 private:
  LabInfo info_;
  scenarios::p1b::Controller control_;
  std::unique_ptr<scenarios::p1b::Loop> loop_;
  scenarios::p1b::Result result_;
  Eigen::VectorXd tau_;
  Eigen::Vector3d x_d_;
};

}  // namespace opspace::live
