#include "command.hpp"

#include <string>

namespace opspace::programs {

int parse_p4(int argc, char** argv, int (*usage)(const char*, int), P4Command& command) {
  using opspace::hw2::p4::Target;
  Program program;
  program.usage = usage;
  program.csv = false;  // one log per run, named after the target
  program.extra = [&](const std::string& arg) {
    if (arg == "z") {
      command.targets = {Target::kAlongZ0};
    } else if (arg == "y") {
      command.targets = {Target::kAlongY0};
    } else if (arg == "all") {
      command.targets = {Target::kAlongZ0, Target::kAlongY0};
    } else {
      return false;
    }
    return true;
  };
  return parse(argc, argv, 1, program, command.options);
}

}  // namespace opspace::programs
