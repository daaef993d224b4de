// Runner of problem 1c: the control law of exercises/p1c.cpp (problems/1c/contract.hpp).
#include "untrusted/serve.hpp"

namespace opspace::runner {

OPSPACE_RUNNER_DISPATCH(OPSPACE_P1C_FUNCTIONS)

}  // namespace opspace::runner
