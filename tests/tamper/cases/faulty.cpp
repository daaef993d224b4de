// A 1b controller that misbehaves as a student's might: FAULT is segfault, hang, throw or nan.
#include <problems/1b/contract.hpp>

#include <limits>
#include <string>
#include <stdexcept>

namespace opspace::hw2::p1b {
Vector6d control(Part, const State& s, const Goal&) {
  const std::string fault = "@FAULT@";
  if (fault == "segfault") {
    volatile double* nowhere = nullptr;
    nowhere[static_cast<int>(s.t)] = 1.0;  // writes through a null pointer
  } else if (fault == "hang") {
    for (volatile unsigned long spin = 0; spin != 1; spin = spin + 2) {
    }
  } else if (fault == "throw") {
    throw std::out_of_range("index out of range");
  }
  return Vector6d::Constant(std::numeric_limits<double>::quiet_NaN());
}
}  // namespace opspace::hw2::p1b
