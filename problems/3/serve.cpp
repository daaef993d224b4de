// Runner of problem 3: the functions of exercises/p3.cpp (problems/3/contract.hpp).
#include "untrusted/serve.hpp"

namespace opspace::runner {

OPSPACE_RUNNER_DISPATCH(OPSPACE_P3_FUNCTIONS)

}  // namespace opspace::runner
