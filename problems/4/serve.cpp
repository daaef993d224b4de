// Runner of problem 4: the functions of exercises/p4.cpp (problems/4/contract.hpp).
#include "untrusted/serve.hpp"

namespace opspace::runner {

OPSPACE_RUNNER_DISPATCH(OPSPACE_P4_FUNCTIONS)

}  // namespace opspace::runner
