/// @file problems/3/functions.hpp
/// Problem 3's student functions (problems/3/contract.hpp), one row each: the only list
/// of them. problems.hpp says what is derived from the rows and how; problems/1a/functions.hpp what a
/// row holds.
#pragma once

#include <problems/3/contract.hpp>

#define OPSPACE_P3_FUNCTIONS(F)                                                              \
  F(p3, 0x0301, kP3MotionSelection, motion_selection) /* 3(a): Omega */                      \
  F(p3, 0x0302, kP3ForceSelection, force_selection)   /* 3(a): Omega-bar */                  \
  F(p3, 0x0303, kP3Control, control)                  /* 3(b): the unified motion and force law */

// How the protocol encodes this problem's structs (grader/protocol/codec.hpp): each field once,
// in order, for both directions.
namespace opspace::hw2::p3 {
template <class S, class F>
void fields(S& s, F&& f, Goal*) {
  f(s.x_d), f(s.xdot_d), f(s.xddot_d), f(s.F_d), f(s.kpx), f(s.kvx), f(s.kvj);
}
}  // namespace opspace::hw2::p3
