// Runner of problem 4: the functions of exercises/p4.cpp (lib/include/opspace/hw2/p4.hpp).
#include "serve.hpp"

namespace opspace::runner {

bool dispatch(protocol::Function function, protocol::Reader& in, protocol::Writer& out) {
  namespace p4 = hw2::p4;
  using F = protocol::Function;
  switch (function) {
    case F::kP4DegreesOfFreedom: serve(&p4::degrees_of_freedom, in, out); return true;
    case F::kP4SingularDirections: serve(&p4::singular_directions, in, out); return true;
    case F::kP4MovingDirections: serve(&p4::moving_directions, in, out); return true;
    case F::kP4RotationAxes: serve(&p4::rotation_axes, in, out); return true;
    case F::kP4SingularityType: serve(&p4::singularity_type, in, out); return true;
    case F::kP4Control: serve(&p4::control, in, out); return true;
    default: return false;
  }
}

}  // namespace opspace::runner
