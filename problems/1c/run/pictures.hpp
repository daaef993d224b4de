/// @file problems/1c/run/pictures.hpp
/// Problem 1c's pictures of a run: problem 1b's (tip against its target, tip error, torques, the
/// 3D replay) and the joint speeds, which nothing damps.
#pragma once

#include <vector>

#include "opspace/visuals/plot.hpp"
#include "opspace/visuals/replay.hpp"
#include <problems/1c/run/scenario.hpp>

namespace opspace::scenarios::p1c {

/// Figures "tip", "error", "torques" (problem 1b's) and "speeds" (|dq_i| of each joint).
std::vector<plot::Figure> figures(const Result& result);

/// The replay: the PUMA, x_d, the tip's path (problem 1b's).
replay::Scene replay_scene(const Result& result);

}  // namespace opspace::scenarios::p1c
