// Runner of problem 1a: the functions of exercises/p1a.cpp (problems/1a/contract.hpp).
#include "untrusted/serve.hpp"

namespace opspace::runner {

OPSPACE_RUNNER_DISPATCH(OPSPACE_P1A_FUNCTIONS)

}  // namespace opspace::runner
