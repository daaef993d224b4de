/// @file linked_api.hpp
/// The functions linked into a test program of our own (the reference solutions, to which the
/// mutants swap in known-wrong variants): the suite's own tests grade them in-process. The
/// grader never includes this header: it does not link a student's code.
#pragma once

#include "api.hpp"

namespace opspace::grading {

/// The hw2 functions this program links.
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
  api.identity = 1;
  return api;
}

}  // namespace opspace::grading
