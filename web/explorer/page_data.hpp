/// @file page_data.hpp
/// What the explorer page is handed about each robot, as JSON: its Model as text, joints and
/// their limits, the configuration it opens at, and its scene for the viewer.
#pragma once

#include <string>
#include <vector>

#include "robots.hpp"

namespace opspace::explore {

/// One robot's entry of the page's data block. A joint limit that is unbounded (a continuous
/// joint, or no <limit>) is written as null: JSON has no infinity (web/src/explorer.js then
/// gives the slider one turn, or one metre, on that side of q0).
std::string robot_json(const Robot& robot);

/// The page's whole data block, {"robots": [one entry per robot]}.
std::string page_data_json(const std::vector<Robot>& robots);

}  // namespace opspace::explore
