// Attack: fill the disk, in the work folder and in /tmp.
// The first calls of each runner write up to the sandbox's file size limit; every later call
// could only truncate and write the same files again, which cost 19 s of kernel time in the
// simulation tests (thousands of calls) and proves nothing more.
#include <problems/1b/contract.hpp>

#include <cstdio>
#include <vector>

namespace opspace::hw2::p1b {
Vector6d control(Part, const State&, const Goal&) {
  static int calls = 0;
  if (calls++ < 3) {
    const std::vector<char> block(1 << 20, 'x');
    for (const char* path : {"@WORK@/flood.bin", "flood.bin", "/tmp/flood.bin"}) {
      if (FILE* f = std::fopen(path, "w")) {
        for (int i = 0; i < 300; ++i) std::fwrite(block.data(), 1, block.size(), f);
        std::fclose(f);
      }
    }
  }
  return Vector6d::Zero();
}
}  // namespace opspace::hw2::p1b
