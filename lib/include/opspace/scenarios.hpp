/// @file scenarios.hpp
/// Each problem's setup (robot, operational point, initial state, goal, gains) and its
/// closed-loop run on the simulation: one header per problem in scenarios/.
#pragma once

#include "opspace/scenarios/common.hpp"
#include "opspace/scenarios/p1b.hpp"
#include "opspace/scenarios/p2.hpp"
#include "opspace/scenarios/p3.hpp"
#include "opspace/scenarios/p4.hpp"
