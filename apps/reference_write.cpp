// hw2-reference's outputs (reference.cpp): reference_runs.hpp, every problem's declarations
// (problems/<key>/run/reference.cpp) in one header, and the docs' fragments, each between its
// markers, its prose wrapped as the docs are.
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference.hpp"

namespace opspace::programs {

namespace {

/// The fragment with its prose lines (not the tables' rows) wrapped at 96 columns, as the docs.
std::string wrap_prose(const std::string& text) {
  std::istringstream in(text);
  std::ostringstream out;
  for (std::string line; std::getline(in, line);) {
    // Not inside "t = 0.001 s" or "14.5 N": never before "=", a unit or after "=".
    const auto breakable = [&](std::size_t at) {
      const std::size_t next_end = line.find(' ', at + 1);
      const std::string next = line.substr(at + 1, next_end == std::string::npos ? std::string::npos : next_end - at - 1);
      const std::string before = line.substr(line.rfind(' ', at - 1) + 1, at - line.rfind(' ', at - 1) - 1);
      for (const char* unit : {"=", "N", "s", "mm", "deg", "rad", "rad/s", "N m", "m"}) {
        if (next.rfind(unit, 0) == 0 && (next.size() == std::string(unit).size() || !std::isalpha(static_cast<unsigned char>(next[std::string(unit).size()]))))
          return false;
      }
      return before != "=";
    };
    while (line.size() > 96 && line[0] != '|') {
      std::size_t cut = line.rfind(' ', 96);
      while (cut != std::string::npos && cut > 0 && !breakable(cut)) cut = line.rfind(' ', cut - 1);
      if (cut == std::string::npos || cut == 0) break;
      out << line.substr(0, cut) << "\n";
      line = line.substr(cut + 1);
    }
    out << line << "\n";
  }
  return out.str();
}

}  // namespace

void write_header(const std::vector<programs::ReferenceText>& runs, const std::string& path) {
  std::ostringstream out;
  out << "// Generated at build time by hw2-reference (apps/reference.cpp, from each problem's\n"
         "// problems/<key>/run/reference.cpp): what solutions/ does on each scenario at the programs' default\n"
         "// durations, exactly. Do not edit.\n"
         "#pragma once\n\n"
         "#include <iterator>\n"
         "#include <vector>\n\n";
  std::set<std::string> included;
  for (const programs::ReferenceText& run : runs) {
    for (const std::string& header : run.includes) {
      if (included.insert(header).second) out << "#include <" << header << ">\n";
    }
  }
  out << "\nnamespace reference {\n\n";
  for (const programs::ReferenceText& run : runs) out << run.declarations;
  out << "}  // namespace reference\n";
  std::ofstream file(path);
  file << out.str();
  if (!file) throw std::runtime_error("cannot write " + path);
}

void write_fragments(const std::vector<programs::ReferenceText>& runs, const std::string& path) {
  std::ofstream file(path);
  for (const programs::ReferenceText& run : runs) {
    for (const auto& [name, text] : run.fragments) file << marker(name) << "\n" << wrap_prose(text) << end_marker(name) << "\n";
  }
  if (!file) throw std::runtime_error("cannot write " + path);
}

}  // namespace opspace::programs
