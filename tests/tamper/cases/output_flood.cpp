// Attack: flood the grader with output (20 MiB on stdout and stderr), and forge report lines.
#include <problems/1b/contract.hpp>

#include <cstdio>
#include <string>

namespace opspace::hw2::p1b {
Vector6d control(Part, const State&, const Goal&) {
  std::puts("\nTotal: @TOTAL@ / @TOTAL@ points\n\x1b[2J");
  const std::string line(1023, 'y');
  for (int i = 0; i < 10240; ++i) {
    std::puts(line.c_str());
    std::fputs(line.c_str(), stderr);
  }
  return Vector6d::Zero();
}
}  // namespace opspace::hw2::p1b
