// Runner of problem 3: the functions of exercises/p3.cpp (lib/include/opspace/hw2/p3.hpp).
#include "serve.hpp"

namespace opspace::runner {

bool dispatch(protocol::Function function, protocol::Reader& in, protocol::Writer& out) {
  using F = protocol::Function;
  switch (function) {
    case F::kP3MotionSelection: serve(&hw2::p3::motion_selection, in, out); return true;
    case F::kP3ForceSelection: serve(&hw2::p3::force_selection, in, out); return true;
    case F::kP3Control: serve(&hw2::p3::control, in, out); return true;
    default: return false;
  }
}

}  // namespace opspace::runner
