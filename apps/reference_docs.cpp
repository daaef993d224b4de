// hw2-reference docs check|write (reference.cpp): the generated fragments of docs/*.md and of
// the problems' guides (problems/*/guide.md) against this build's reference runs. `check`
// (ctest) accepts the same text and numbers, where a paragraph wraps aside, and a "~" value
// within a factor of 2; `write` (the refresh-docs target) replaces each fragment with this
// build's.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference.hpp"

namespace opspace::programs {

namespace {

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot read " + path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(file, line);) lines.push_back(line);
  return lines;
}

/// The name of a "<!-- generated: NAME ..." line, or "".
std::string generated_name(const std::string& line) {
  const std::string start = "<!-- generated: ";
  if (line.rfind(start, 0) != 0) return "";
  const std::size_t end = line.find_first_of(" ", start.size());
  return line.substr(start.size(), end - start.size());
}

std::map<std::string, std::vector<std::string>> read_fragments(const std::string& path) {
  std::map<std::string, std::vector<std::string>> fragments;
  std::string name;
  for (const std::string& line : lines_of(path)) {
    if (const std::string n = generated_name(line); !n.empty()) {
      name = n;
      fragments[name];
    } else if (line == end_marker(name)) {
      name.clear();
    } else if (!name.empty()) {
      fragments[name].push_back(line);
    }
  }
  return fragments;
}

/// A line cut into numbers ("~" and "-" included) and the text between them.
std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> out;
  std::string text;
  for (std::size_t i = 0; i < line.size();) {
    std::size_t j = i;
    if (line[j] == '~') ++j;
    if (j < line.size() && line[j] == '-' && j + 1 < line.size() && std::isdigit(static_cast<unsigned char>(line[j + 1])))
      ++j;
    if (j < line.size() && std::isdigit(static_cast<unsigned char>(line[j]))) {
      while (j < line.size() && (std::isdigit(static_cast<unsigned char>(line[j])) || line[j] == '.')) ++j;
      out.push_back(text);
      out.push_back(line.substr(i, j - i));
      text.clear();
      i = j;
    } else {
      text += line[i++];
    }
  }
  out.push_back(text);
  return out;
}

/// The docs' line agrees with the fresh one: the same text, the same numbers, except that a
/// number marked "~" may differ by a factor of 2. Round-off differs between machines (the
/// C library picks its sin, cos and exp by CPU), and such values move by percents with it.
bool docs_line_matches(const std::string& docs_line, const std::string& fresh_line) {
  const std::vector<std::string> a = tokens(docs_line), b = tokens(fresh_line);
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] == b[i]) continue;
    if (i % 2 == 0 || a[i][0] != '~' || b[i][0] != '~') return false;
    const double x = std::stod(a[i].substr(1)), y = std::stod(b[i].substr(1));
    if (!(x * y > 0.0 && std::max(x / y, y / x) <= 2.0)) return false;
  }
  return true;
}

/// The lines as one text, every run of white space one space: where a paragraph wraps does
/// not matter (a number one digit longer moves the break).
std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) {
    for (char c : line + "\n") {
      const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
      if (!space) text += c;
      else if (!text.empty() && text.back() != ' ') text += ' ';
    }
  }
  return text;
}

bool docs_match(const std::vector<std::string>& docs_lines, const std::vector<std::string>& fresh) {
  return docs_line_matches(joined(docs_lines), joined(fresh));
}

/// The pages that may quote the reference runs: DIR/*.md and each problem's guide,
/// DIR/../problems/<key>/guide.md.
std::vector<std::filesystem::path> pages(const std::string& dir) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() == ".md") files.push_back(entry.path());
  }
  for (const auto& entry : fs::directory_iterator((fs::path(dir) / ".." / "problems").lexically_normal())) {
    const fs::path guide = entry.path() / "guide.md";
    if (entry.is_directory() && fs::exists(guide)) files.push_back(guide);
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

int docs(bool write, const std::string& dir, const std::string& fragments_path) {
  const auto fragments = read_fragments(fragments_path);
  std::map<std::string, int> used;
  int stale = 0;
  for (const std::filesystem::path& path : pages(dir)) {
    const std::vector<std::string> lines = lines_of(path.string());
    std::vector<std::string> out;
    bool changed = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      out.push_back(lines[i]);
      const std::string name = generated_name(lines[i]);
      if (name.empty()) continue;
      const auto fragment = fragments.find(name);
      if (fragment == fragments.end()) {
        std::cerr << path.string() << ":" << i + 1 << ": unknown generated fragment '" << name << "'\n";
        return 1;
      }
      std::size_t end = i + 1;
      while (end < lines.size() && lines[end] != end_marker(name)) ++end;
      if (end == lines.size()) {
        std::cerr << path.string() << ":" << i + 1 << ": no '" << end_marker(name) << "' after this line\n";
        return 1;
      }
      ++used[name];
      const std::vector<std::string> current(lines.begin() + static_cast<long>(i) + 1,
                                             lines.begin() + static_cast<long>(end));
      if (write ? current != fragment->second : !docs_match(current, fragment->second)) {
        changed = true;
        if (!write) {
          ++stale;
          std::cerr << path.string() << ":" << i + 2 << ": the fragment '" << name
                    << "' differs from this build's reference run.\n  in the docs:\n";
          for (const std::string& l : current) std::cerr << "    " << l << "\n";
          std::cerr << "  from the run:\n";
          for (const std::string& l : fragment->second) std::cerr << "    " << l << "\n";
        }
      }
      out.insert(out.end(), fragment->second.begin(), fragment->second.end());
      out.push_back(lines[end]);
      i = end;
    }
    if (write && changed) {
      std::ofstream file(path);
      for (const std::string& l : out) file << l << "\n";
      if (!file) throw std::runtime_error("cannot write " + path.string());
      std::cout << "updated " << path.string() << "\n";
    }
  }
  for (const auto& [name, text] : fragments) {
    if (used[name] == 0) {
      std::cerr << "the fragment '" << name << "' appears in no page (" << dir
                << "/*.md, problems/*/guide.md)\n";
      ++stale;
    }
  }
  if (stale > 0 && !write) {
    std::cerr << "\nThe docs quote reference runs that this build no longer produces. If the change is\n"
                 "intended, refresh them: cmake --build build/release --target refresh-docs\n";
  }
  return stale > 0 ? 1 : 0;
}

}  // namespace opspace::programs
