// What the files of hw2-reference share (reference.cpp says what the program does): writing the
// problems' reference runs out, and the markers around a generated fragment of the docs, which
// reference_write.cpp writes and reference_docs.cpp finds.
#pragma once

#include <string>
#include <vector>

#include "opspace/programs/reference_text.hpp"

namespace opspace::programs {

/// reference_write.cpp: reference_runs.hpp, every problem's declarations in namespace reference.
void write_header(const std::vector<programs::ReferenceText>& runs, const std::string& path);

/// reference_write.cpp: the docs' fragments of every problem, each between its markers.
void write_fragments(const std::vector<programs::ReferenceText>& runs, const std::string& path);

/// reference_docs.cpp: `docs check` (write false) or `docs write`; the exit code.
int docs(bool write, const std::string& dir, const std::string& fragments_path);

inline std::string marker(const std::string& name) {
  return "<!-- generated: " + name + " (hw2-reference; cmake --build build/release --target refresh-docs) -->";
}
inline std::string end_marker(const std::string& name) { return "<!-- end generated: " + name + " -->"; }

}  // namespace opspace::programs
