// Runner of problem 1b: the control law of exercises/p1b.cpp (problems/1b/contract.hpp).
#include "untrusted/serve.hpp"

namespace opspace::runner {

OPSPACE_RUNNER_DISPATCH(OPSPACE_P1B_FUNCTIONS)

}  // namespace opspace::runner
