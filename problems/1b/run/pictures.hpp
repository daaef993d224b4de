/// @file problems/1b/run/pictures.hpp
/// Problem 1b's pictures of a run: the plots (tip against its target, tracking errors, joint
/// 2 against q_d, torques against the URDF effort limits), the 3D replay scene, and the
/// PART2-against-PART3 drift comparison that is the lesson of the problem.
#pragma once

#include <vector>

#include "opspace/visuals/plot.hpp"
#include "opspace/visuals/replay.hpp"
#include <problems/1b/run/scenario.hpp>

namespace opspace::scenarios::p1b {

/// Figures "tip", "error", "q2" (PART2 and PART3 only) and "torques" of one run.
std::vector<plot::Figure> figures(const Result& result, hw2::p1b::Part part);

/// The replay: the PUMA, the desired tip x_d, the tip's path, tip error and q2 read-outs.
replay::Scene replay_scene(const Result& result, hw2::p1b::Part part);

/// Figure "drift": the tip error and joint 2 of a PART2 run and a PART3 run, overlaid.
plot::Figure compare_figure(const Result& part2, const Result& part3);

}  // namespace opspace::scenarios::p1b
