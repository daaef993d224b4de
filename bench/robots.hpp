// The robots, operational points and joint states that bench_dynamics and its peers time, in
// one place so that every program times the same calls on the same states.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <vector>

#include "opspace/model/catalogue.hpp"

namespace opspace::bench {

/// A course robot and the operational point of its task (opspace/model/catalogue.hpp):
/// 0 = iiwa7, problem 2's link7 origin; 1 = PUMA, problem 1b's tip.
using Robot = catalogue::CourseRobot;
inline constexpr std::array<Robot, 2> kRobots{catalogue::kIiwa, catalogue::kPuma};

/// The cycle of states a benchmark steps through, one per iteration (a control loop never
/// calls twice at the same state): q_k = linspace(-1, 1) sin(0.1 k), qdot_k = linspace(0.5, -0.5) cos(0.1 k).
inline constexpr int kStates = 64;
inline std::vector<Eigen::VectorXd> positions(int dof) {
  std::vector<Eigen::VectorXd> q;
  for (int k = 0; k < kStates; ++k) q.push_back(Eigen::VectorXd::LinSpaced(dof, -1.0, 1.0) * std::sin(0.1 * k));
  return q;
}
inline std::vector<Eigen::VectorXd> velocities(int dof) {
  std::vector<Eigen::VectorXd> qdot;
  for (int k = 0; k < kStates; ++k) qdot.push_back(Eigen::VectorXd::LinSpaced(dof, 0.5, -0.5) * std::cos(0.1 * k));
  return qdot;
}

}  // namespace opspace::bench
