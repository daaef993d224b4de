// Attack: exhaust the machine's memory.
#include <problems/1b/contract.hpp>

#include <cstring>
#include <vector>

namespace opspace::hw2::p1b {
Vector6d control(Part, const State&, const Goal&) {
  std::vector<char*> blocks;
  for (int i = 0; i < 12; ++i) {  // 12 GiB, touched
    char* block = new char[1ul << 30];
    std::memset(block, 1, 1ul << 30);
    blocks.push_back(block);
  }
  return Vector6d::Constant(static_cast<double>(blocks.size()));
}
}  // namespace opspace::hw2::p1b
