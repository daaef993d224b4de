// Runner of problem 1b: the control law of exercises/p1b.cpp (lib/include/opspace/hw2/p1b.hpp).
#include "serve.hpp"

namespace opspace::runner {

bool dispatch(protocol::Function function, protocol::Reader& in, protocol::Writer& out) {
  if (function != protocol::Function::kP1bControl) return false;
  serve(&hw2::p1b::control, in, out);
  return true;
}

}  // namespace opspace::runner
