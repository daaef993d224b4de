/// @file temporary_folder.hpp
/// The grader's temporary folders, each tracked while it lives, so that an interrupted grading
/// removes them too (sandbox/interrupt.hpp): an interrupted grading leaves nothing in /tmp.
#pragma once

#include <string>
#include <vector>

namespace opspace::grading {

/// Remembers a temporary folder this process created, to be removed if it is interrupted.
void track_folder(const std::string& path);
/// Forgets it (it was removed, or is no longer temporary).
void forget_folder(const std::string& path);
/// The folders tracked now.
std::vector<std::string> tracked_folders();

/// A temporary folder made by mkdtemp() from `prefix` ("/tmp/opspace-build-") and the grader's
/// pid ("/tmp/opspace-build-4242-Xy12Ab": a check can tell its folders from another grading's),
/// tracked while it lives, removed with its contents when it goes out of scope.
class TemporaryFolder {
 public:
  /// Throws std::runtime_error if the folder cannot be made.
  explicit TemporaryFolder(const std::string& prefix);
  ~TemporaryFolder();
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace opspace::grading
