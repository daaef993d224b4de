/// @file functions.hpp
/// The table of the student's functions: each Hw2Api member with its protocol code. The
/// remote api, the recording of a test's calls and the replay of known mistakes all walk it.
#pragma once

#include <string>

#include "api.hpp"
#include "protocol/protocol.hpp"

namespace opspace::grading {

/// Calls visit(code, member) for every function of `api`.
template <class Api, class Visit>
void for_each_function(Api& api, Visit&& visit) {
  using F = protocol::Function;
  visit(F::kP1aDegreesOfFreedom, api.p1a.degrees_of_freedom);
  visit(F::kP1aMassMatrix, api.p1a.mass_matrix);
  visit(F::kP1aTaskJacobian, api.p1a.task_jacobian);
  visit(F::kP1aPseudoInverse, api.p1a.pseudo_inverse);
  visit(F::kP1aWeightedInverse, api.p1a.weighted_inverse);
  visit(F::kP1aInertiaWeightedInverse, api.p1a.inertia_weighted_inverse);
  visit(F::kP1aNullspaceProjector, api.p1a.nullspace_projector);
  visit(F::kP1aInverseKinematicsStep, api.p1a.inverse_kinematics_step);
  visit(F::kP1aSplitDisplacement, api.p1a.split_displacement);
  visit(F::kP1bControl, api.p1b.control);
  visit(F::kP2DesiredAcceleration, api.p2.desired_acceleration);
  visit(F::kP2DesiredTwistAcceleration, api.p2.desired_twist_acceleration);
  visit(F::kP2Control, api.p2.control);
  visit(F::kP3MotionSelection, api.p3.motion_selection);
  visit(F::kP3ForceSelection, api.p3.force_selection);
  visit(F::kP3Control, api.p3.control);
  visit(F::kP4DegreesOfFreedom, api.p4.degrees_of_freedom);
  visit(F::kP4SingularDirections, api.p4.singular_directions);
  visit(F::kP4MovingDirections, api.p4.moving_directions);
  visit(F::kP4RotationAxes, api.p4.rotation_axes);
  visit(F::kP4SingularityType, api.p4.singularity_type);
  visit(F::kP4Control, api.p4.control);
}

/// The problem a function belongs to: "1a", "1b", "2", "3" or "4" (the code's high byte).
inline std::string problem_of(protocol::Function function) {
  switch (static_cast<unsigned>(function) >> 8) {
    case 0x1a: return "1a";
    case 0x1b: return "1b";
    case 0x02: return "2";
    case 0x03: return "3";
    case 0x04: return "4";
    default: return "";
  }
}

}  // namespace opspace::grading
