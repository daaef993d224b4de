/// @file problems/1a/functions.hpp
/// Problem 1a's student functions (problems/1a/contract.hpp), one row each: the only
/// list of them. problems.hpp says what is derived from the rows and how.
///
/// F(problem, code, Code, name): the contract's namespace (hw2::problem), the protocol code
/// (the problem's byte high; a code is never reused or renumbered), the protocol's enumerator
/// (protocol::Function::Code) and the function's name in the contract. After the table, the
/// fields of the contract's structs, as the protocol encodes them (grader/protocol/codec.hpp).
#pragma once

#include <problems/1a/contract.hpp>

#define OPSPACE_P1A_FUNCTIONS(F)                                                                                  \
  F(p1a, 0x1a01, kP1aDegreesOfFreedom, degrees_of_freedom)             /* question i: task and robot DOF */        \
  F(p1a, 0x1a02, kP1aMassMatrix, mass_matrix)                          /* question ii: A */                        \
  F(p1a, 0x1a03, kP1aTaskJacobian, task_jacobian)                      /* question iii: J */                       \
  F(p1a, 0x1a04, kP1aPseudoInverse, pseudo_inverse)                    /* question iv: J+ */                       \
  F(p1a, 0x1a05, kP1aWeightedInverse, weighted_inverse)                /* question v: J# */                        \
  F(p1a, 0x1a06, kP1aInertiaWeightedInverse, inertia_weighted_inverse) /* question vi: Jbar */                     \
  F(p1a, 0x1a07, kP1aNullspaceProjector, nullspace_projector)          /* questions iv-vi: I - J_inv J */          \
  F(p1a, 0x1a08, kP1aInverseKinematicsStep, inverse_kinematics_step)   /* iv-vi: dq = J_inv dx + N dq0 */          \
  F(p1a, 0x1a09, kP1aSplitDisplacement, split_displacement)            /* question vi: dq with J+ and with Jbar */

// How the protocol encodes this problem's structs (grader/protocol/codec.hpp): each field once,
// in order, for both directions.
namespace opspace::hw2::p1a {
template <class S, class F>
void fields(S& s, F&& f, DegreesOfFreedom*) {
  f(s.task), f(s.robot), f(s.redundant);
}
template <class S, class F>
void fields(S& s, F&& f, DisplacementSplit*) {
  f(s.with_pseudo_inverse), f(s.with_inertia_weighted);
}
}  // namespace opspace::hw2::p1a
