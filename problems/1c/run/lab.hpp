/// @file problems/1c/run/lab.hpp
/// Problem 1c live (docs/live.md): a LoopLab over its scenario (live/loop_lab.hpp) with one law,
/// the tip PD without joint damping. A push sets the undamped null space moving, and it keeps
/// moving after you let go. Plots: the tip error and the fastest joint's speed.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "opspace/live/loop_lab.hpp"
#include <problems/1c/run/scenario.hpp>

namespace opspace::live {

class P1cLab final : public LoopLab<scenarios::p1b::Scenario> {
 public:
  P1cLab(const std::string& program, scenarios::p1c::Controller control);
  void plot_values(std::vector<double>& values) const override;
  void marker_positions(std::vector<Eigen::Vector3d>& positions) const override;
};

}  // namespace opspace::live
