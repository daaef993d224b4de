/// @file opspace/hw2/p1c.hpp
/// (problems/1c/contract.hpp, which the build copies where it is included: <opspace/hw2/p1c.hpp>)
/// Problem 1c: the PUMA 560 of problem 1b holds its tip with PART1's tip PD and no joint damping
/// (the problem set's question ii): what the joints do when nothing damps the null space.
/// Declared here, written by the student in exercises/p1c.cpp, by the instructor in
/// solutions/p1c.cpp.
#pragma once

#include <opspace/hw2/p1b.hpp>  // the PUMA's State and Goal, as problem 1b's

namespace opspace::hw2::p1c {

using p1b::Goal;
using p1b::State;
using p1b::Vector6d;

/// The joint torques Gamma of the tip PD without joint damping.
Vector6d control(const State& state, const Goal& goal);

}  // namespace opspace::hw2::p1c
