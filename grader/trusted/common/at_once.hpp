/// @file at_once.hpp
/// A loop whose iterations run several at once: the runners' builds, one compiler per core,
/// and the problems' gradings (--jobs).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace opspace::grading {

/// Calls `each(i)` for every i below `count`, `jobs` at once: this thread and jobs - 1 others
/// take the next i in turn.
template <typename Each>
void at_once(std::size_t count, unsigned jobs, Each each) {
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t i = next++; i < count; i = next++) each(i);
  };
  std::vector<std::thread> threads;
  for (std::size_t j = 1; j < std::min<std::size_t>(jobs, count); ++j) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
}

}  // namespace opspace::grading
