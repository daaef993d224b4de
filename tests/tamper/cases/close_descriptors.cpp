// Attack: close every descriptor and keep running, so that the grader waits forever.
#include <problems/1b/contract.hpp>
#include <unistd.h>

namespace opspace::hw2::p1b {
Vector6d control(Part, const State&, const Goal&) {
  for (int fd = 0; fd < 1024; ++fd) close(fd);
  for (volatile unsigned long spin = 0;; spin = spin + 1) {
  }
  return Vector6d::Zero();
}
}  // namespace opspace::hw2::p1b
