/// @file problems/4/functions.hpp
/// Problem 4's student functions (problems/4/contract.hpp), one row each: the only list
/// of them. problems.hpp says what is derived from the rows and how; problems/1a/functions.hpp what a
/// row holds.
#pragma once

#include <problems/4/contract.hpp>

#define OPSPACE_P4_FUNCTIONS(F)                                                                          \
  F(p4, 0x0401, kP4DegreesOfFreedom, degrees_of_freedom)   /* i. the rank of Jv */                       \
  F(p4, 0x0402, kP4SingularDirections, singular_directions) /* ii. u with u^T Jv = 0 */                  \
  F(p4, 0x0403, kP4MovingDirections, moving_directions)     /* iii. directions the tip can move along */ \
  F(p4, 0x0404, kP4RotationAxes, rotation_axes)             /* iii. axes the tip can rotate about */     \
  F(p4, 0x0405, kP4SingularityType, singularity_type)       /* iv. Type I or Type II */                  \
  F(p4, 0x0406, kP4Control, control)                        /* v. the control law near the singularity */

// How the protocol encodes this problem's structs (grader/protocol/codec.hpp): each field once,
// in order, for both directions.
namespace opspace::hw2::p4 {
template <class S, class F>
void fields(S& s, F&& f, Kinematics*) {
  f(s.q), f(s.x), f(s.Jv), f(s.Jw), f(s.H);
}
template <class S, class F>
void fields(S& s, F&& f, Directions*) {
  f(s.count), f(s.u);
}
template <class S, class F>
void fields(S& s, F&& f, State*) {
  f(s.t), f(s.q), f(s.dq), f(s.x), f(s.dx), f(s.Jv), f(s.A), f(s.g), f(s.Lambda_v), f(s.Jbar_v), f(s.N), f(s.p);
}
template <class S, class F>
void fields(S& s, F&& f, Goal*) {
  f(s.x_d), f(s.kpx), f(s.kvx), f(s.kpj), f(s.kvj);
}
}  // namespace opspace::hw2::p4
