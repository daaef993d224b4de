/// @file problems/1c/run/scenario.hpp
/// Problem 1c's run: problem 1b's scenario (the PUMA from q(0) at rest, x_d, the gains) with
/// problem 1c's law applied at every tick.
#pragma once

#include <functional>

#include <opspace/hw2/p1c.hpp>
#include <problems/1b/run/scenario.hpp>

namespace opspace::scenarios::p1c {

using p1b::Result;
using p1b::Scenario;

/// The control function under test: exercises/ or solutions/ (hw2::p1c::control), or a mutant.
using Controller = std::function<hw2::p1c::Vector6d(const hw2::p1c::State&, const hw2::p1c::Goal&)>;

/// Problem 1b's scenario (its "PART1 without joint damping") under `control`.
Scenario scenario(Controller control);

/// Runs it every 1 ms step for options.duration.
Result run(Controller control, const RunOptions& options);

/// The graded run's bound on the tip error after 2 s (m). An arm without control falls under
/// gravity: its tip leaves x_d by decimetres (free fall covers g t^2 / 2 = 0.3 m in 0.25 s), while
/// the tip PD holds it even with its null space undamped, within centimetres: the reference run's
/// largest error is 6.6 cm (hw2-reference's table in problems/1c/guide.md). 15 cm separates them.
inline constexpr double kTipErrorMax = 0.15;

}  // namespace opspace::scenarios::p1c
