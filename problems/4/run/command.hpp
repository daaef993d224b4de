// hw2-p4's command line (problem 4's program): the targets of question v, then programs::parse()'s
// options. tests/apps/test_cli.cpp checks it and tests/fuzz/fuzz_cli.cpp fuzzes it.
#pragma once

#include <vector>

#include <problems/4/contract.hpp>

#include "opspace/programs/cli.hpp"

namespace opspace::programs {

/// hw2-p4's command line: z, y or all (the last one given counts) and parse()'s options but
/// --csv (each run names its own log).
struct P4Command {
  std::vector<opspace::hw2::p4::Target> targets = {opspace::hw2::p4::Target::kAlongZ0,
                                                   opspace::hw2::p4::Target::kAlongY0};
  Options options;  ///< run.duration: set the default before parsing
};

/// Parses hw2-p4's argv into `command` (usage: the program's); returns as parse() does.
int parse_p4(int argc, char** argv, int (*usage)(const char*, int), P4Command& command);

}  // namespace opspace::programs
