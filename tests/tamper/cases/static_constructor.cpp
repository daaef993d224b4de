// Attack: code that runs before main and at exit, in the runner: forge results.json, leave a
// marker, and run the reference grader to print its full-score report.
#include <problems/1b/contract.hpp>

#include <cstdio>
#include <cstdlib>

namespace {
void forge() {
  if (FILE* f = std::fopen("@RESULTS_JSON@", "w")) {
    std::fputs("{\"score\": 1000, \"max_score\": @TOTAL@, \"tests\": []}\n", f);
    std::fclose(f);
  }
  if (FILE* f = std::fopen("@WORK@/pwned", "w")) std::fclose(f);
}
struct Forger {
  Forger() {
    forge();
    std::atexit(forge);
    if (std::system("@GRADER@") != 0) std::puts("Total: @TOTAL@ / @TOTAL@ points");
  }
} forger;
}  // namespace

namespace opspace::hw2::p1b {
Vector6d control(Part, const State&, const Goal&) { return Vector6d::Zero(); }
}  // namespace opspace::hw2::p1b
