#include "command.hpp"

#include <iostream>
#include <string>

namespace opspace::programs {

int parse_p1(int argc, char** argv, int (*usage)(const char*, int), P1Command& command) {
  using opspace::hw2::p1b::Part;
  if (argc < 2) return usage(argv[0], 2);
  const std::string part = argv[1];
  if (part == "--help" || part == "-h") return usage(argv[0], 0);
  command.comparing = part == "compare";
  if (part == "1") {
    command.part = Part::kTipPd;
  } else if (part == "2" || command.comparing) {
    command.part = Part::kPseudoInverseNullspace;
  } else if (part == "3") {
    command.part = Part::kDynamicallyConsistentNullspace;
  } else {
    std::cerr << argv[0] << ": unknown part '" << part << "'\n";
    return usage(argv[0], 2);
  }
  Program program;
  program.usage = usage;
  program.help = false;  // only as the first argument
  std::string misplaced;  // --no-joint-damping where it does not apply
  program.extra = [&](const std::string& arg) {
    if (arg != "--no-joint-damping") return false;
    if (command.part == Part::kTipPd && !command.comparing) {
      command.part = Part::kTipPdWithoutJointDamping;
    } else if (command.part != Part::kTipPdWithoutJointDamping) {
      misplaced = "--no-joint-damping applies to PART 1 only, not to '" + part + "'";
    }
    return true;
  };
  command.options.run.csv_path.clear();  // still empty after parse(): no --csv given
  const int code = parse(argc, argv, 2, program, command.options);
  if (code >= 0) return code;
  if (!misplaced.empty()) return refuse(argv[0], misplaced);
  // compare runs PART2 and PART3 offline, one after the other; the live page switches PART.
  if (command.comparing && command.options.live)
    return refuse(argv[0], "'--live' does not apply to 'compare' (it runs PART2 and PART3 offline): "
                           "run 'hw2-p1 2 --live' or 'hw2-p1 3 --live' and switch the PART on the page");
  if (command.options.run.csv_path.empty()) {
    command.options.run.csv_path =
        output_path(program_name(argv[0]) + (command.comparing ? "-compare.csv"
                                             : command.part == Part::kTipPdWithoutJointDamping ? "-part1-no-damping.csv"
                                                                                                : "-part" + part + ".csv"));
  }
  return -1;
}

}  // namespace opspace::programs
