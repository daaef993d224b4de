/// @file interrupt.hpp
/// A grader stopped by Ctrl-C (SIGINT), `timeout` or a closed terminal (SIGTERM, SIGHUP)
/// stops the programs it started and removes its temporary folders (common/temporary_folder.hpp)
/// before it ends, as it does when it finishes: an interrupted grading leaves nothing in /tmp.
#pragma once

namespace opspace::grading {

/// From now on SIGINT, SIGTERM and SIGHUP kill the sandboxed programs, remove the tracked
/// folders and end the process with status 128 + the signal. Call it before any thread starts:
/// the threads inherit the blocked signals, which one watching thread takes with sigwait(). A
/// signal that was ignored when the grader started (nohup, a background job) stays ignored.
void clean_up_when_interrupted();

}  // namespace opspace::grading
