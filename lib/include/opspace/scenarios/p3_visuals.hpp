/// @file scenarios/p3_visuals.hpp
/// Problem 3's plots of a run: the contact force against F_d = 10 N with the moments about y
/// and z, the tracked y, z and rotation about x against their goals, and the tool's tilt.
/// (No replay scene yet.)
#pragma once

#include <vector>

#include "opspace/plot.hpp"
#include "opspace/scenarios/p3.hpp"

namespace opspace::scenarios::p3 {

/// Figures "force" (F_x with its 10 ms average and F_d; M_y, M_z), "tracking" (y, z against
/// y_d, z_d; the rotation-about-x error) and "tilt" of one run.
std::vector<plot::Figure> figures(const Result& result);

}  // namespace opspace::scenarios::p3
