// What the files of hw2-reference share (reference.cpp says what the program does): the
// reference runs, and the markers around a generated fragment of the docs, which
// reference_fragments.cpp writes and reference_docs.cpp finds.
#pragma once

#include <map>
#include <string>

#include <opspace/hw2/p1b.hpp>
#include <opspace/hw2/p4.hpp>
#include <problems/1b/scenario.hpp>
#include <problems/2/scenario.hpp>
#include <problems/3/scenario.hpp>
#include <problems/4/scenario.hpp>

namespace hw2_reference {

namespace sc = opspace::scenarios;
namespace p1b = opspace::scenarios::p1b;
namespace p2 = opspace::scenarios::p2;
namespace p3 = opspace::scenarios::p3;
namespace p4 = opspace::scenarios::p4;
using Part = opspace::hw2::p1b::Part;
using Target = opspace::hw2::p4::Target;

inline constexpr Part kParts[] = {Part::kTipPd, Part::kTipPdWithoutJointDamping, Part::kPseudoInverseNullspace,
                                  Part::kDynamicallyConsistentNullspace};
inline constexpr Target kTargets[] = {Target::kAlongZ0, Target::kAlongY0};

/// Every reference run, at the programs' default durations.
struct Runs {
  std::map<Part, p1b::Result> p1b;
  p2::Result p2;
  p3::Result p3;
  std::map<Target, p4::Result> p4, p4_plain;
};

/// reference_header.cpp: reference_runs.hpp, the Summary of each run as exact C++.
void write_header(const Runs& runs, const std::string& path);

/// reference_fragments.cpp: the docs' tables of the reference runs, one fragment each.
void write_fragments(const Runs& runs, const std::string& path);

/// reference_docs.cpp: `docs check` (write false) or `docs write`; the exit code.
int docs(bool write, const std::string& dir, const std::string& fragments_path);

inline std::string marker(const std::string& name) {
  return "<!-- generated: " + name + " (hw2-reference; cmake --build build/release --target refresh-docs) -->";
}
inline std::string end_marker(const std::string& name) { return "<!-- end generated: " + name + " -->"; }

}  // namespace hw2_reference
