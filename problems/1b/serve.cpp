// Runner of problem 1b: the control law of exercises/p1b.cpp (lib/include/opspace/hw2/p1b.hpp).
#include "untrusted/serve.hpp"

namespace opspace::runner {

OPSPACE_RUNNER_DISPATCH(OPSPACE_P1B_FUNCTIONS)

}  // namespace opspace::runner
