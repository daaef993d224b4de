/// @file problems/2/functions.hpp
/// Problem 2's student functions (problems/2/contract.hpp), one row each: the only list
/// of them. problems.hpp says what is derived from the rows and how; problems/1a/functions.hpp what a
/// row holds.
#pragma once

#include <problems/2/contract.hpp>

#define OPSPACE_P2_FUNCTIONS(F)                                                                            \
  F(p2, 0x0201, kP2DesiredAcceleration, desired_acceleration)            /* 2(a): xddot_d(t) */            \
  F(p2, 0x0202, kP2DesiredTwistAcceleration, desired_twist_acceleration) /* 2(b): E^+ xddot_d */           \
  F(p2, 0x0203, kP2Control, control)                                     /* 2(c): the tracking law */

// How the protocol encodes this problem's structs (grader/protocol/codec.hpp): each field once,
// in order, for both directions.
namespace opspace::hw2::p2 {
template <class S, class F>
void fields(S& s, F&& f, State*) {
  f(s.t), f(s.q), f(s.dq), f(s.x_p), f(s.lambda), f(s.v), f(s.w), f(s.J0), f(s.A), f(s.g), f(s.Lambda0),
      f(s.Jbar0), f(s.N0), f(s.p);
}
template <class S, class F>
void fields(S& s, F&& f, Goal*) {
  f(s.x_d), f(s.xdot_d), f(s.xddot_d), f(s.kpx), f(s.kvx), f(s.kvj);
}
}  // namespace opspace::hw2::p2
