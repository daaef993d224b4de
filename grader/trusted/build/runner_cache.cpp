// The runners' cache, bounded (runner_cache.hpp). Entries: runner-<key>-<hash> and its
// .report; held-<pid>-<key>, a grading's hard link to what it runs; <entry>.tmp<pid>, a copy
// being written. A runner's last use is its modification time, set at each use.
#include "build/runner_cache.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "common/process_ended.hpp"
#include "common/size_text.hpp"

namespace fs = std::filesystem;

namespace opspace::grading {

namespace {

bool starts_with(const std::string& text, const std::string& prefix) { return text.compare(0, prefix.size(), prefix) == 0; }

// The pid a leftover's name carries after `marker` ("held-42-1b", "x.tmp42"), or 0.
long pid_after(const std::string& name, const std::string& marker) {
  const std::size_t at = name.rfind(marker);
  return at == std::string::npos ? 0 : std::strtol(name.c_str() + at + marker.size(), nullptr, 10);
}

struct Entry {
  fs::path runner;
  fs::file_time_type used;
  unsigned long long bytes = 0;
};

unsigned long long size_of(const fs::path& path) {
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  return ec ? 0 : size;
}

}  // namespace

std::string hold_runner(const std::string& cached, const std::string& cache_dir, const std::string& key) {
  utimensat(AT_FDCWD, cached.c_str(), nullptr, 0);  // used now
  const std::string held = cache_dir + "/held-" + std::to_string(getpid()) + "-" + key;
  unlink(held.c_str());
  if (link(cached.c_str(), held.c_str()) != 0)
    throw std::runtime_error("the grader could not hold its runner " + cached + ": " + std::strerror(errno));
  return held;
}

CacheState prune_runner_cache(const std::string& cache_dir, unsigned long long bound_bytes) {
  CacheState state;
  std::vector<Entry> entries;
  std::error_code ec;
  const std::string own = "held-" + std::to_string(getpid()) + "-";
  for (const fs::directory_entry& file : fs::directory_iterator(cache_dir, ec)) {
    const std::string name = file.path().filename().string();
    const bool held = starts_with(name, "held-") && (starts_with(name, own) || process_ended(pid_after(name, "held-")));
    const bool unfinished = name.find(".tmp") != std::string::npos && process_ended(pid_after(name, ".tmp"));
    const bool leftover = held || unfinished;
    if (leftover) {
      fs::remove(file.path(), ec);
    } else if (starts_with(name, "runner-") && name.find('.') == std::string::npos) {
      entries.push_back({file.path(), file.last_write_time(ec), size_of(file.path()) + size_of(file.path().string() + ".report")});
    }
  }
  // The least recently used first, removed until the rest fits.
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
  for (const Entry& entry : entries) state.bytes += entry.bytes;
  state.runners = entries.size();
  for (std::size_t i = 0; i < entries.size() && state.bytes > bound_bytes; ++i) {
    fs::remove(entries[i].runner, ec);
    fs::remove(entries[i].runner.string() + ".report", ec);
    state.bytes -= entries[i].bytes;
    state.pruned_bytes += entries[i].bytes;
    --state.runners;
    ++state.pruned;
  }
  return state;
}

std::string CacheState::line(unsigned long long bound_bytes) const {
  std::string text = "runner cache: " + std::to_string(runners) + " runner(s), " + size_text(bytes) + " of its " +
                     size_text(bound_bytes) + " bound";
  if (pruned > 0) text += "; " + std::to_string(pruned) + " least recently used removed (" + size_text(pruned_bytes) + ")";
  return text;
}

}  // namespace opspace::grading
