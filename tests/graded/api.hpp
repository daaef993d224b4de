/// @file api.hpp
/// The student-written functions, gathered as function pointers so that the graded suite
/// is compiled once and run against exercises/, solutions/ or a known-wrong variant.
#pragma once

#include <opspace/hw2/p1a.hpp>
#include <opspace/hw2/p1b.hpp>
#include <opspace/hw2/p2.hpp>
#include <opspace/hw2/p3.hpp>
#include <opspace/hw2/p4.hpp>

namespace opspace::grading {

/// Problem 1a (lib/include/opspace/hw2/p1a.hpp).
struct P1aApi {
  decltype(&hw2::p1a::degrees_of_freedom) degrees_of_freedom;              ///< question i: task and robot DOF
  decltype(&hw2::p1a::mass_matrix) mass_matrix;                            ///< question ii: A
  decltype(&hw2::p1a::task_jacobian) task_jacobian;                        ///< question iii: J
  decltype(&hw2::p1a::pseudo_inverse) pseudo_inverse;                      ///< question iv: J+
  decltype(&hw2::p1a::weighted_inverse) weighted_inverse;                  ///< question v: J#
  decltype(&hw2::p1a::inertia_weighted_inverse) inertia_weighted_inverse;  ///< question vi: Jbar
  decltype(&hw2::p1a::nullspace_projector) nullspace_projector;            ///< questions iv-vi: I - J_inv J
  decltype(&hw2::p1a::inverse_kinematics_step) inverse_kinematics_step;    ///< questions iv-vi: dq = J_inv dx + N dq0
  decltype(&hw2::p1a::split_displacement) split_displacement;              ///< question vi: dq with J+ and with Jbar
};

/// Problem 1b (lib/include/opspace/hw2/p1b.hpp).
struct P1bApi {
  decltype(&hw2::p1b::control) control;  ///< the torques of each PART
};

/// Problem 2 (lib/include/opspace/hw2/p2.hpp).
struct P2Api {
  decltype(&hw2::p2::desired_acceleration) desired_acceleration;              ///< 2(a): xddot_d(t)
  decltype(&hw2::p2::desired_twist_acceleration) desired_twist_acceleration;  ///< 2(b): E^+ xddot_d
  decltype(&hw2::p2::control) control;                                        ///< 2(c): the tracking law
};

/// Problem 3 (lib/include/opspace/hw2/p3.hpp).
struct P3Api {
  decltype(&hw2::p3::motion_selection) motion_selection;  ///< 3(a): Omega
  decltype(&hw2::p3::force_selection) force_selection;    ///< 3(a): Omega-bar
  decltype(&hw2::p3::control) control;                    ///< 3(b): the unified motion and force law
};

/// Problem 4 (lib/include/opspace/hw2/p4.hpp).
struct P4Api {
  decltype(&hw2::p4::degrees_of_freedom) degrees_of_freedom;    ///< i. the rank of Jv
  decltype(&hw2::p4::singular_directions) singular_directions;  ///< ii. u with u^T Jv = 0
  decltype(&hw2::p4::moving_directions) moving_directions;      ///< iii. directions the tip can move along
  decltype(&hw2::p4::rotation_axes) rotation_axes;              ///< iii. axes the tip can rotate about
  decltype(&hw2::p4::singularity_type) singularity_type;        ///< iv. Type I or Type II
  decltype(&hw2::p4::control) control;                          ///< v. the control law near the singularity
};

/// Every graded function of problem set 2.
struct Hw2Api {
  P1aApi p1a;  ///< problem 1a
  P1bApi p1b;  ///< problem 1b
  P2Api p2;    ///< problem 2
  P3Api p3;    ///< problem 3
  P4Api p4;    ///< problem 4
};

/// The implementation linked into this program: exercises/ in hw2-grade, solutions/ in
/// hw2-grade-sol. Inline, so that each program binds the library it links.
inline Hw2Api linked_api() {
  namespace p1a = hw2::p1a;
  Hw2Api api{};
  api.p1a = {&p1a::degrees_of_freedom, &p1a::mass_matrix,       &p1a::task_jacobian,
             &p1a::pseudo_inverse,     &p1a::weighted_inverse,  &p1a::inertia_weighted_inverse,
             &p1a::nullspace_projector, &p1a::inverse_kinematics_step, &p1a::split_displacement};
  api.p1b = {&hw2::p1b::control};
  api.p2 = {&hw2::p2::desired_acceleration, &hw2::p2::desired_twist_acceleration, &hw2::p2::control};
  api.p3 = {&hw2::p3::motion_selection, &hw2::p3::force_selection, &hw2::p3::control};
  api.p4 = {&hw2::p4::degrees_of_freedom, &hw2::p4::singular_directions, &hw2::p4::moving_directions,
            &hw2::p4::rotation_axes,      &hw2::p4::singularity_type,    &hw2::p4::control};
  return api;
}

}  // namespace opspace::grading
