/// @file problems/1b/functions.hpp
/// Problem 1b's student functions (problems/1b/contract.hpp), one row each: the only
/// list of them. problems.hpp says what is derived from the rows and how; problems/1a/functions.hpp
/// what a row holds.
#pragma once

#include <opspace/hw2/p1b.hpp>

#define OPSPACE_P1B_FUNCTIONS(F) \
  F(p1b, 0x1b01, kP1bControl, control) /* the torques of each PART */
