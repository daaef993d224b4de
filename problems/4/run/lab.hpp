/// @file problems/4/run/lab.hpp
/// Problem 4 live (docs/live.md): a LoopLab over its scenario (live/loop_lab.hpp) that adds
/// what is its own: what its page plots and marks, the laws it switches between, its gains' ranges.
/// It records its current run as the offline run's Result. `program` names the program serving
/// the page (its log's and the terminal's name, the page's heading).
#pragma once

#include <string>

#include "opspace/live/loop_lab.hpp"
#include <problems/4/run/scenario.hpp>

namespace opspace::live {

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
