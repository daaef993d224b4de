/// @file grader.hpp
/// The grading command behind hw2-grade, the trusted side: it builds each problem's runner
/// from that problem's exercise file, asks the runner for the student's values, judges them
/// against its oracles, and writes the report, results.json and JUnit XML. It never links,
/// loads or runs a student's code in its own process. grader.cpp is its pipeline, stage by
/// stage (README.md in this folder).
#pragma once

#include <string>

namespace opspace::grading {

/// The whole command: parses argv, grades the exercise files in `default_exercises` (or
/// --exercises), prints, writes the requested files. Returns the exit code: 0 when grading ran
/// (whatever the score), 2 for a bad command line, 1 when an output file cannot be written or
/// the grader itself is broken.
int grader_main(int argc, char** argv, const std::string& default_exercises);


}  // namespace opspace::grading
