/// @file problems/3/run/lab.hpp
/// Problem 3 live (docs/live.md): a LoopLab over its scenario (live/loop_lab.hpp) that adds
/// what is its own: what its page plots and marks, its gains' ranges.
/// It records its current run as the offline run's Result. `program` names the program serving
/// the page (its log's and the terminal's name, the page's heading).
#pragma once

#include <string>

#include "opspace/live/loop_lab.hpp"
#include <problems/3/run/scenario.hpp>

namespace opspace::live {

/// Problem 3: the tool pushes 10 N on the plane; pull it off and let it come back. Plots: F_x
/// with its 10 ms mean against 10 N, the tool's tilt.
class P3Lab final : public LoopLab<scenarios::p3::Scenario> {
 public:
  P3Lab(const std::string& program, scenarios::p3::Controller control);
  void plot_values(std::vector<double>& values) const override;
  void marker_positions(std::vector<Eigen::Vector3d>& positions) const override;
};

}  // namespace opspace::live
