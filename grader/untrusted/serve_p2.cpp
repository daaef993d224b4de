// Runner of problem 2: the functions of exercises/p2.cpp (lib/include/opspace/hw2/p2.hpp).
#include "serve.hpp"

namespace opspace::runner {

bool dispatch(protocol::Function function, protocol::Reader& in, protocol::Writer& out) {
  using F = protocol::Function;
  switch (function) {
    case F::kP2DesiredAcceleration: serve(&hw2::p2::desired_acceleration, in, out); return true;
    case F::kP2DesiredTwistAcceleration: serve(&hw2::p2::desired_twist_acceleration, in, out); return true;
    case F::kP2Control: serve(&hw2::p2::control, in, out); return true;
    default: return false;
  }
}

}  // namespace opspace::runner
