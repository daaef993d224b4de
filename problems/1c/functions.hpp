/// @file problems/1c/functions.hpp
/// Problem 1c's student functions (problems/1c/contract.hpp), one row each: the only list of
/// them (problems/1a/functions.hpp says what a row holds). Its structs are problem 1b's, whose
/// fields problems/1b/functions.hpp lists.
#pragma once

#include <opspace/hw2/p1c.hpp>

#include "problems/1b/functions.hpp"

#define OPSPACE_P1C_FUNCTIONS(F) \
  F(p1c, 0x1c01, kP1cControl, control) /* the tip PD without joint damping */
