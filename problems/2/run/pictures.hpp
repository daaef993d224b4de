/// @file problems/2/run/pictures.hpp
/// The pictures of a problem-2 run (docs/visuals.md): plots and the 3D replay scene.
#pragma once

#include <vector>

#include "opspace/visuals/plot.hpp"
#include "opspace/visuals/replay.hpp"
#include <problems/2/run/scenario.hpp>

namespace opspace::scenarios::p2 {

/// link7's position against x_d(t); position and orientation errors; torques against limits.
std::vector<plot::Figure> figures(const Result& result);

/// The iiwa replayed with the moving target x_d(t) and the path of link7's origin.
replay::Scene replay_scene(const Result& result);

}  // namespace opspace::scenarios::p2
