// Runner of problem 4: the functions of exercises/p4.cpp (lib/include/opspace/hw2/p4.hpp).
#include "untrusted/serve.hpp"

namespace opspace::runner {

OPSPACE_RUNNER_DISPATCH(OPSPACE_P4_FUNCTIONS)

}  // namespace opspace::runner
