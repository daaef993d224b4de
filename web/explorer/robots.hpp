/// @file robots.hpp
/// The four robots of the explorer page: the course's robots (opspace/model/catalogue.hpp),
/// each with the configuration the page opens at and what the page says about it.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "explore.hpp"
#include "opspace/model/model.hpp"

namespace opspace::explore {

struct Robot {
  std::string key;      ///< short name: pp, puma, iiwa, rrr
  std::string title;    ///< shown in the robot menu
  std::string caption;  ///< one paragraph in the problem set's words
  Model model;
  std::string tip_link;
  Tip tip;
  Eigen::VectorXd q0;   ///< the configuration the page opens at
  int self_joint = 0;   ///< the joint whose self-motion the page shows first
};

/// The four robots, loaded from robots/ (throws as load_urdf does).
std::vector<Robot> course_robots();

/// The robot `key`; throws std::invalid_argument listing the keys.
Robot course_robot(const std::string& key);

}  // namespace opspace::explore
