// Runner of problem 5: the function of exercises/p5.cpp (problems/5/contract.hpp).
#include "untrusted/serve.hpp"

namespace opspace::runner {

OPSPACE_RUNNER_DISPATCH(OPSPACE_P5_FUNCTIONS)

}  // namespace opspace::runner
