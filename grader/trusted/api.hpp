/// @file api.hpp
/// The student-written functions of each problem, as std::function members: the graded suite
/// is written once against this struct, and the grader fills it with functions that ask a
/// problem's runner (remote_api.hpp), while the suite's own tests fill it with the reference
/// solutions and known-wrong variants linked into the test program (linked_api.hpp).
#pragma once

#include <opspace/hw2/p1a.hpp>
#include <opspace/hw2/p1b.hpp>
#include <opspace/hw2/p2.hpp>
#include <opspace/hw2/p3.hpp>
#include <opspace/hw2/p4.hpp>

#include <cstdint>
#include <functional>

namespace opspace::grading {

/// A function with the type of a student function, e.g. Fn<decltype(hw2::p1b::control)>.
template <class F>
using Fn = std::function<F>;

/// Problem 1a (lib/include/opspace/hw2/p1a.hpp).
struct P1aApi {
  Fn<decltype(hw2::p1a::degrees_of_freedom)> degrees_of_freedom;              ///< question i: task and robot DOF
  Fn<decltype(hw2::p1a::mass_matrix)> mass_matrix;                            ///< question ii: A
  Fn<decltype(hw2::p1a::task_jacobian)> task_jacobian;                        ///< question iii: J
  Fn<decltype(hw2::p1a::pseudo_inverse)> pseudo_inverse;                      ///< question iv: J+
  Fn<decltype(hw2::p1a::weighted_inverse)> weighted_inverse;                  ///< question v: J#
  Fn<decltype(hw2::p1a::inertia_weighted_inverse)> inertia_weighted_inverse;  ///< question vi: Jbar
  Fn<decltype(hw2::p1a::nullspace_projector)> nullspace_projector;            ///< questions iv-vi: I - J_inv J
  Fn<decltype(hw2::p1a::inverse_kinematics_step)> inverse_kinematics_step;    ///< questions iv-vi: dq = J_inv dx + N dq0
  Fn<decltype(hw2::p1a::split_displacement)> split_displacement;              ///< question vi: dq with J+ and with Jbar
};

/// Problem 1b (lib/include/opspace/hw2/p1b.hpp).
struct P1bApi {
  Fn<decltype(hw2::p1b::control)> control;  ///< the torques of each PART
};

/// Problem 2 (lib/include/opspace/hw2/p2.hpp).
struct P2Api {
  Fn<decltype(hw2::p2::desired_acceleration)> desired_acceleration;              ///< 2(a): xddot_d(t)
  Fn<decltype(hw2::p2::desired_twist_acceleration)> desired_twist_acceleration;  ///< 2(b): E^+ xddot_d
  Fn<decltype(hw2::p2::control)> control;                                        ///< 2(c): the tracking law
};

/// Problem 3 (lib/include/opspace/hw2/p3.hpp).
struct P3Api {
  Fn<decltype(hw2::p3::motion_selection)> motion_selection;  ///< 3(a): Omega
  Fn<decltype(hw2::p3::force_selection)> force_selection;    ///< 3(a): Omega-bar
  Fn<decltype(hw2::p3::control)> control;                    ///< 3(b): the unified motion and force law
};

/// Problem 4 (lib/include/opspace/hw2/p4.hpp).
struct P4Api {
  Fn<decltype(hw2::p4::degrees_of_freedom)> degrees_of_freedom;    ///< i. the rank of Jv
  Fn<decltype(hw2::p4::singular_directions)> singular_directions;  ///< ii. u with u^T Jv = 0
  Fn<decltype(hw2::p4::moving_directions)> moving_directions;      ///< iii. directions the tip can move along
  Fn<decltype(hw2::p4::rotation_axes)> rotation_axes;              ///< iii. axes the tip can rotate about
  Fn<decltype(hw2::p4::singularity_type)> singularity_type;        ///< iv. Type I or Type II
  Fn<decltype(hw2::p4::control)> control;                          ///< v. the control law near the singularity
};

/// Every graded function of problem set 2.
struct Hw2Api {
  P1aApi p1a;  ///< problem 1a
  P1bApi p1b;  ///< problem 1b
  P2Api p2;    ///< problem 2
  P3Api p3;    ///< problem 3
  P4Api p4;    ///< problem 4
  /// Tells implementations apart: the simulated runs, shared by several tests, are cached
  /// per identity. Each runner set, the reference and each known-wrong variant has its own.
  std::uint64_t identity = 0;
};

}  // namespace opspace::grading
