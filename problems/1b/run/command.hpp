// hw2-p1's command line (problem 1b's program): PART first, then programs::parse()'s options.
// tests/apps/test_cli.cpp checks it and tests/fuzz/fuzz_cli.cpp fuzzes it.
#pragma once

#include <problems/1b/contract.hpp>

#include "opspace/programs/cli.hpp"

namespace opspace::programs {

/// hw2-p1's command line: PART first (1, 2, 3 or compare; --help and -h only there), then
/// --no-joint-damping (PART 1 only) and parse()'s options but --help.
struct P1Command {
  opspace::hw2::p1b::Part part = opspace::hw2::p1b::Part::kTipPd;
  bool comparing = false;  ///< PART "compare": PART2 and PART3, their drift overlaid
  Options options;         ///< csv_path defaults to out/hw2-p1-part<PART>[-no-damping].csv
};

/// Parses hw2-p1's argv into `command` (usage: the program's); returns as parse() does.
int parse_p1(int argc, char** argv, int (*usage)(const char*, int), P1Command& command);

}  // namespace opspace::programs
