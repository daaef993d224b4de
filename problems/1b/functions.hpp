/// @file problems/1b/functions.hpp
/// Problem 1b's student functions (problems/1b/contract.hpp), one row each: the only
/// list of them. problems.hpp says what is derived from the rows and how; problems/1a/functions.hpp
/// what a row holds.
#pragma once

#include <problems/1b/contract.hpp>

#define OPSPACE_P1B_FUNCTIONS(F) \
  F(p1b, 0x1b01, kP1bControl, control) /* the torques of each PART */

// How the protocol encodes this problem's structs (grader/protocol/codec.hpp): each field once,
// in order, for both directions.
namespace opspace::hw2::p1b {
template <class S, class F>
void fields(S& s, F&& f, State*) {
  f(s.t), f(s.q), f(s.dq), f(s.x), f(s.dx), f(s.Jv), f(s.A), f(s.g), f(s.Lambda_v), f(s.Jbar_v), f(s.p);
}
template <class S, class F>
void fields(S& s, F&& f, Goal*) {
  f(s.x_d), f(s.q_d), f(s.kpx), f(s.kvx), f(s.kpj), f(s.kvj);
}
}  // namespace opspace::hw2::p1b
