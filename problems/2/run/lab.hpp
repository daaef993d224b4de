/// @file problems/2/run/lab.hpp
/// Problem 2 live (docs/live.md): a LoopLab over its scenario (live/loop_lab.hpp) that adds
/// what is its own: what its page plots and marks, its gains' ranges.
/// It records its current run as the offline run's Result. `program` names the program serving
/// the page (its log's and the terminal's name, the page's heading).
#pragma once

#include <string>

#include "opspace/live/loop_lab.hpp"
#include <problems/2/run/scenario.hpp>

namespace opspace::live {

/// Problem 2: the iiwa tracks its trajectory; push the elbow while it tracks. Plots: position
/// and orientation error.
class P2Lab final : public LoopLab<scenarios::p2::Scenario> {
 public:
  P2Lab(const std::string& program, scenarios::p2::Controller control,
        scenarios::p2::DesiredAcceleration desired_acceleration);
  void plot_values(std::vector<double>& values) const override;
  void marker_positions(std::vector<Eigen::Vector3d>& positions) const override;
};

}  // namespace opspace::live
