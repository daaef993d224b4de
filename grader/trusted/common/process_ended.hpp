/// @file process_ended.hpp
/// Whether the process a leftover's name carries has ended: what lets a grader remove the files
/// and groups that a killed grading left behind, and never those of one still running.
#pragma once

#include <signal.h>
#include <sys/types.h>

#include <cerrno>

namespace opspace::grading {

/// True if no process `pid` exists (kill's signal 0 finds none: ESRCH). False for pid <= 0 and
/// for a process this grader may not signal (EPERM: it exists).
inline bool process_ended(long pid) { return pid > 0 && kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH; }

}  // namespace opspace::grading
