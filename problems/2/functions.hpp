/// @file problems/2/functions.hpp
/// Problem 2's student functions (problems/2/contract.hpp), one row each: the only list
/// of them. problems.hpp says what is derived from the rows and how; problems/1a/functions.hpp what a
/// row holds.
#pragma once

#include <opspace/hw2/p2.hpp>

#define OPSPACE_P2_FUNCTIONS(F)                                                                            \
  F(p2, 0x0201, kP2DesiredAcceleration, desired_acceleration)            /* 2(a): xddot_d(t) */            \
  F(p2, 0x0202, kP2DesiredTwistAcceleration, desired_twist_acceleration) /* 2(b): E^+ xddot_d */           \
  F(p2, 0x0203, kP2Control, control)                                     /* 2(c): the tracking law */
