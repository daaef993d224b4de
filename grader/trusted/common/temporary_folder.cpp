#include "common/temporary_folder.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>
#include <stdexcept>
#include <system_error>

namespace opspace::grading {

namespace {

std::mutex& folders_lock() {
  static std::mutex lock;
  return lock;
}

std::set<std::string>& folders() {
  static std::set<std::string> tracked;
  return tracked;
}

}  // namespace

void track_folder(const std::string& path) {
  const std::lock_guard<std::mutex> hold(folders_lock());
  folders().insert(path);
}

void forget_folder(const std::string& path) {
  const std::lock_guard<std::mutex> hold(folders_lock());
  folders().erase(path);
}

std::vector<std::string> tracked_folders() {
  const std::lock_guard<std::mutex> hold(folders_lock());
  return {folders().begin(), folders().end()};
}

TemporaryFolder::TemporaryFolder(const std::string& prefix) {
  std::string pattern = prefix + std::to_string(getpid()) + "-XXXXXX";
  if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a folder " + pattern + ": " + std::strerror(errno));
  path_ = pattern;
  track_folder(path_);
}

TemporaryFolder::~TemporaryFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
  forget_folder(path_);
}

}  // namespace opspace::grading
