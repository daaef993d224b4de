/// @file interrupt.hpp
/// A grader stopped by Ctrl-C (SIGINT), `timeout` or a closed terminal (SIGTERM, SIGHUP)
/// stops the programs it started and removes its temporary folders before it ends, as it does
/// when it finishes: an interrupted grading leaves nothing in /tmp.
#pragma once

#include <string>

namespace opspace::grading {

/// Remembers a temporary folder this process created, to be removed if it is interrupted.
void track_folder(const std::string& path);
/// Forgets it (it was removed, or is no longer temporary).
void forget_folder(const std::string& path);

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

/// From now on SIGINT, SIGTERM and SIGHUP kill the sandboxed programs, remove the tracked
/// folders and end the process with status 128 + the signal. Call it before any thread starts:
/// the threads inherit the blocked signals, which one watching thread takes with sigwait(). A
/// signal that was ignored when the grader started (nohup, a background job) stays ignored.
void clean_up_when_interrupted();

}  // namespace opspace::grading
