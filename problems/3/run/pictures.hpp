/// @file problems/3/run/pictures.hpp
/// Problem 3's plots of a run: the contact force against F_d = 10 N with the moments about y
/// and z, the tracked y, z and rotation about x against their goals, and the tool's tilt; and
/// the 3D replay scene: the iiwa, the plane and the arrow of the tool's push.
#pragma once

#include <vector>

#include "opspace/visuals/plot.hpp"
#include "opspace/visuals/replay.hpp"
#include <problems/3/run/scenario.hpp>

namespace opspace::scenarios::p3 {

/// Figures "force" (F_x with its 10 ms average and F_d; M_y, M_z), "tracking" (y, z against
/// y_d, z_d; the rotation-about-x error) and "tilt" of one run.
std::vector<plot::Figure> figures(const Result& result);

/// The replay: the iiwa, the plane x = 0.05, the force the tool applies to it (an arrow at the
/// face's centre, 1 cm per N), the desired y, z of link7's origin and its path, and read-outs
/// of F_x, the tilt and the y, z error.
replay::Scene replay_scene(const Result& result);

}  // namespace opspace::scenarios::p3
