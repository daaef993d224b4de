#include "build/compiler_messages.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <cctype>
#include <sstream>
#include <stdexcept>

#include "common/student_text.hpp"

namespace opspace::grading {

namespace fs = std::filesystem;

std::string read_at_most(const std::string& path, std::size_t limit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  // In pieces, never more than the file holds plus one piece: a limit is a bound, not a size
  // (one buffer of the limit's size cost 1.3 s of zeroed pages per 512 MiB ELF bound).
  constexpr std::size_t kPiece = 1u << 16;
  std::string text;
  while (in && text.size() <= limit) {
    const std::size_t before = text.size();
    text.resize(before + std::min(kPiece, limit + 1 - before));
    in.read(text.data() + before, static_cast<std::streamsize>(text.size() - before));
    text.resize(before + static_cast<std::size_t>(in.gcount()));
  }
  return text;
}

namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); !from.empty() && at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// "FILE includes its contract by its former path: write ... instead of ...; " when `error` is the
// compiler's not finding a contract by the path it had before commit 77461ea
// (<opspace/hw2/p<key>.hpp>, today <problems/<key>/contract.hpp>); else "FILE: ".
std::string former_contract_path(const std::string& error, const std::string& shown_as) {
  // GCC's "fatal error: X: No such file or directory", Clang's "fatal error: 'X' file not found".
  // Matched by hand, not with <regex>: GCC 12 warns (maybe-uninitialized) inside std::regex at
  // -O1 with the sanitizers, and warnings are errors here.
  const std::string prefix = "opspace/hw2/p";
  const std::size_t at = error.find("fatal error: ");
  if (at == std::string::npos) return shown_as + ": ";
  std::size_t i = at + 13;
  if (i < error.size() && error[i] == '\'') ++i;
  if (error.compare(i, prefix.size(), prefix) != 0) return shown_as + ": ";
  i += prefix.size();
  std::string key;  // one or two hexadecimal digits (problems.txt): nothing of the student's
  while (i < error.size() && key.size() < 3 && std::isxdigit(static_cast<unsigned char>(error[i])) &&
         !std::isupper(static_cast<unsigned char>(error[i])))
    key += error[i++];
  if (key.empty() || key.size() > 2 || error.compare(i, 4, ".hpp") != 0) return shown_as + ": ";
  i += 4;
  if (i < error.size() && error[i] == '\'') ++i;
  const std::string rest = error.substr(i);
  if (rest.rfind(": No such file or directory", 0) != 0 && rest.rfind(" file not found", 0) != 0) return shown_as + ": ";
  return shown_as + " includes its contract by its former path: write #include <problems/" + key +
         "/contract.hpp> instead of <opspace/hw2/p" + key + ".hpp>; ";
}

}  // namespace

std::string first_error(const std::string& output, const std::string& work_file, const std::string& shown_as,
                        const std::vector<std::string>& include_roots, const std::string& tool) {
  const std::vector<std::string> all = lines(output);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const std::string& line = all[i];
    const bool error = line.find(" error: ") != std::string::npos || line.find("undefined reference") != std::string::npos;
    if (!error) continue;
    std::string shown = replace_all(line, work_file, shown_as);
    const bool in_student_file = shown.rfind(shown_as, 0) == 0;
    bool in_public_header = false;
    for (const std::string& root : include_roots) in_public_header = in_public_header || line.rfind(root, 0) == 0;
    const bool from_linker = line.find("undefined reference") != std::string::npos;
    // The compiler driver's own errors ("g++: fatal error: ...") quote no file: shown.
    const bool from_driver = line.find(": fatal error: ") != std::string::npos && line.find(".cpp:") == std::string::npos &&
                             line.find(".hpp:") == std::string::npos && line.find(".h:") == std::string::npos;
    if (!in_student_file && !in_public_header && !from_linker && !from_driver) {
      return "a compile error in a file your exercise includes, outside the library's and the system's headers";
    }
    if (from_linker) {
      const std::size_t at = shown.find("undefined reference");
      shown = shown_as + ": " + shown.substr(at);
    }
    // The error on the grader's line itself, quoted: the line each of the problem's tests
    // carries (the source line below it is shown under the problem alone).
    std::string out = former_contract_path(line, shown_as) + "the " + tool + "'s first error: " +
                      student_line(shown, 300, shown.size());
    if (in_student_file && i + 1 < all.size() && !all[i + 1].empty() && all[i + 1][0] == ' ')
      out += "\n" + student_block(all[i + 1], 300, all[i + 1].size());
    return out;
  }
  return "";
}

std::string warnings_of(const std::string& output, const std::string& work_file, const std::string& shown_as,
                        std::size_t limit) {
  std::string out;
  for (const std::string& line : lines(output)) {
    if (line.find(" warning: ") == std::string::npos) continue;
    out += replace_all(line, work_file, shown_as) + "\n";
  }
  return out.empty() ? out : student_block(out, limit, out.size());
}

namespace {

// The files a compilation read, from its dependency file (make syntax: "target: dep dep \").
std::vector<std::string> dependencies(const std::string& depfile) {
  std::string text = read_at_most(depfile, 4u << 20);
  std::vector<std::string> out;
  const std::size_t colon = text.find(": ");
  if (colon == std::string::npos) return out;
  std::string current;
  for (std::size_t i = colon + 2; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\\' && i + 1 < text.size() && (text[i + 1] == '\n' || text[i + 1] == ' ')) {
      if (text[i + 1] == ' ') current += ' ';
      ++i;
      continue;
    }
    if (c == ' ' || c == '\n' || c == '\t') {
      if (!current.empty()) out.push_back(current);
      current.clear();
      continue;
    }
    current += c;
  }
  if (!current.empty()) out.push_back(current);
  return out;
}

bool under(const fs::path& path, const std::string& root) {
  std::error_code ec;
  const fs::path r = fs::weakly_canonical(root, ec);
  const std::string p = path.string(), prefix = r.string();
  return p.size() > prefix.size() && p.compare(0, prefix.size(), prefix) == 0 && p[prefix.size()] == '/';
}

}  // namespace

std::string check_includes(const std::string& depfile, const std::string& work_dir, const std::string& shown_as,
                           const std::vector<std::string>& roots) {
  for (const std::string& dep : dependencies(depfile)) {
    std::error_code ec;
    const fs::path path = fs::weakly_canonical(fs::path(dep).is_absolute() ? fs::path(dep) : fs::path(work_dir) / dep, ec);
    if (path == fs::weakly_canonical(fs::path(work_dir) / fs::path(shown_as).filename(), ec)) continue;
    bool allowed = false;
    for (const std::string& root : roots) allowed = allowed || under(path, root);
    if (!allowed) {
      return shown_as + " includes " + student_line(dep, 200, dep.size()) +
             ": an exercise may include only the library's headers (<opspace/...>), Eigen and the standard library";
    }
  }
  return "";
}

}  // namespace opspace::grading
