// Runner of problem 2: the functions of exercises/p2.cpp (problems/2/contract.hpp).
#include "untrusted/serve.hpp"

namespace opspace::runner {

OPSPACE_RUNNER_DISPATCH(OPSPACE_P2_FUNCTIONS)

}  // namespace opspace::runner
