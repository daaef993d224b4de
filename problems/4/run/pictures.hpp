/// @file problems/4/run/pictures.hpp
/// The pictures of a problem-4 run (docs/visuals.md): question v's controller against the
/// plain operational-space controller from the same start, and the 3D replay of both.
#pragma once

#include <vector>

#include "opspace/visuals/plot.hpp"
#include "opspace/visuals/replay.hpp"
#include <problems/4/run/scenario.hpp>

namespace opspace::scenarios::p4 {

/// The tip's distance to x_d and the joint angles of both runs, and the torques of both
/// against the effort limits: the contrast of question v.
std::vector<plot::Figure> figures(Target target, const Result& mine, const Result& plain);

/// The arm replayed under question v's controller, with the target and both tips' paths.
replay::Scene replay_scene(Target target, const Result& mine, const Result& plain);

}  // namespace opspace::scenarios::p4
