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

/// From now on SIGINT, SIGTERM and SIGHUP kill the sandboxed programs, remove the tracked
/// folders and end the process with status 128 + the signal. Call it before any thread starts:
/// the threads inherit the blocked signals, which one watching thread takes with sigwait(). A
/// signal that was ignored when the grader started (nohup, a background job) stays ignored.
void clean_up_when_interrupted();

}  // namespace opspace::grading
