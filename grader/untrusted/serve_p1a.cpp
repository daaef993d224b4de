// Runner of problem 1a: the functions of exercises/p1a.cpp (lib/include/opspace/hw2/p1a.hpp).
#include "serve.hpp"

namespace opspace::runner {

bool dispatch(protocol::Function function, protocol::Reader& in, protocol::Writer& out) {
  namespace p1a = hw2::p1a;
  using F = protocol::Function;
  switch (function) {
    case F::kP1aDegreesOfFreedom: serve(&p1a::degrees_of_freedom, in, out); return true;
    case F::kP1aMassMatrix: serve(&p1a::mass_matrix, in, out); return true;
    case F::kP1aTaskJacobian: serve(&p1a::task_jacobian, in, out); return true;
    case F::kP1aPseudoInverse: serve(&p1a::pseudo_inverse, in, out); return true;
    case F::kP1aWeightedInverse: serve(&p1a::weighted_inverse, in, out); return true;
    case F::kP1aInertiaWeightedInverse: serve(&p1a::inertia_weighted_inverse, in, out); return true;
    case F::kP1aNullspaceProjector: serve(&p1a::nullspace_projector, in, out); return true;
    case F::kP1aInverseKinematicsStep: serve(&p1a::inverse_kinematics_step, in, out); return true;
    case F::kP1aSplitDisplacement: serve(&p1a::split_displacement, in, out); return true;
    default: return false;
  }
}

}  // namespace opspace::runner
