// A student's file that does not compile (line 5 misses a semicolon).
#include <problems/1b/contract.hpp>

namespace opspace::hw2::p1b {
Vector6d control(Part, const State&, const Goal&) { Vector6d tau = Vector6d::Zero() return tau; }
}  // namespace opspace::hw2::p1b
