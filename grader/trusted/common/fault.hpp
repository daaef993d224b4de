/// @file fault.hpp
/// Who caused a failure of the grading, said where it happens and carried as data: never read
/// back from its text, which may quote the student's. results.json counts the grader's own
/// (extra_data.grader.grader_faults), and scripts/regrade grades those submissions again.
#pragma once

namespace opspace::grading {

enum class Fault {
  none,        ///< nothing failed
  grader,      ///< the grader's own call failed: a pipe, a process or a sandbox it could not start, its own files
  submission,  ///< the submission: it does not compile, is refused, exceeds a bound, crashes or runs out of time
};

}  // namespace opspace::grading
