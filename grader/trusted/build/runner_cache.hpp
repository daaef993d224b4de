/// @file runner_cache.hpp
/// The runners' cache (runner_build.hpp keeps a runner by the hash of its inputs), bounded: at
/// the end of each grading the least recently used runners are removed until the cache holds
/// at most its bound. An honest runner is about 85 KiB (--gc-sections), so a bound of 1 GiB
/// keeps the runners of a class of a thousand at once; a padded one (a 200 MiB array in the
/// exercise file) is kept only as long as the bound allows and pushes out the oldest first.
/// A grading holds what it uses by a link of its own (removed when it ends), so that a grading
/// running at once never removes a runner from under another.
#pragma once

#include <string>

namespace opspace::grading {

/// The default bound, in MiB (hw2-grade --cache-limit).
constexpr unsigned long long kDefaultCacheMib = 1024;

/// Marks `cached` as just used and links it, for this grading, as `<cache_dir>/held-<pid>-<key>`:
/// the path to run it from until the grading ends. Throws std::runtime_error if the link fails.
std::string hold_runner(const std::string& cached, const std::string& cache_dir, const std::string& key);

/// The cache after a pruning, for the log.
struct CacheState {
  unsigned long long runners = 0, bytes = 0;        ///< kept
  unsigned long long pruned = 0, pruned_bytes = 0;  ///< removed now
  std::string line(unsigned long long bound_bytes) const;  ///< "runner cache: 12 runner(s), 1.1 MiB of its 1024 MiB bound ..."
};

/// Removes this grading's links, what graders that have ended left behind (links, unfinished
/// copies), then the least recently used runners (with their reports) until at most
/// `bound_bytes` are kept.
CacheState prune_runner_cache(const std::string& cache_dir, unsigned long long bound_bytes);

}  // namespace opspace::grading
