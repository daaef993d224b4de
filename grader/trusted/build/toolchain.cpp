#include "build/toolchain.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "common/sha256.hpp"

namespace opspace::grading {

namespace fs = std::filesystem;

namespace {

// Which grader this is, part of the cache key: a runner and its report (the calls to oracles,
// the include check) are reused only by the grader that made them, never by one built since
// with other oracles or rules. The executable's size, time and inode (a rebuilt grader is a
// new file), read with stat: hashing its bytes would cost seconds in a debug build. Empty where
// /proc is not mounted.
std::string own_identity() {
  struct stat self {};
  if (stat("/proc/self/exe", &self) != 0) return "";
  return std::to_string(self.st_size) + " " + std::to_string(self.st_mtim.tv_sec) + "." +
         std::to_string(self.st_mtim.tv_nsec) + " " + std::to_string(self.st_ino) + " " + std::to_string(self.st_dev);
}

// What the compiler may read of this build's headers, part of the cache key: every file under
// the `headers=` folders (the library's include/, the contracts' copies), its path, size and
// time, in name order. A header added, edited or removed there by hand, with no rebuild of the
// grader, then builds anew instead of being served a runner compiled without it.
std::string headers_state(const std::vector<std::string>& roots) {
  std::vector<std::string> entries;
  for (const std::string& root : roots) {
    std::error_code ec;
    for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
      struct stat st {};
      if (lstat(it->path().c_str(), &st) != 0 || S_ISDIR(st.st_mode)) continue;
      entries.push_back(it->path().string() + " " + std::to_string(st.st_mode) + " " + std::to_string(st.st_size) +
                        " " + std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec));
    }
    if (ec) entries.push_back(root + " unreadable: " + ec.message());
  }
  std::sort(entries.begin(), entries.end());
  std::string all;
  for (const std::string& entry : entries) all += std::to_string(entry.size()) + " " + entry + "\n";
  return all;
}

}  // namespace

Toolchain load_toolchain(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read the runner toolchain (was the grader built?)");
  Toolchain t;
  std::string line, all;
  for (int number = 1; std::getline(in, line); ++number) {
    all += line + "\n";
    if (line.empty() || line[0] == '#') continue;
    const std::size_t eq = line.find('=');
    if (eq == std::string::npos) throw std::runtime_error(path + ":" + std::to_string(number) + ": expected KEY=VALUE");
    const std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    if (value.empty()) continue;  // a generator expression that is empty in this configuration
    if (key == "compile") t.compile.push_back(value);
    else if (key == "link") t.link.push_back(value);
    else if (key == "include") t.include_roots.push_back(value);
    else if (key == "headers") t.headers.push_back(value);
    else if (key == "archive") t.archives.push_back(value);
    else if (key == "nm") t.nm = value;
    else if (key == "nm-plugin") t.nm_plugin = value;
    else if (key.rfind("inputs-", 0) == 0) {
      const std::string problem = key.substr(7);
      auto it = std::find_if(t.inputs.begin(), t.inputs.end(), [&](const auto& p) { return p.first == problem; });
      if (it == t.inputs.end()) it = t.inputs.insert(t.inputs.end(), {problem, {}});
      it->second.push_back(value);
    } else {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": unknown key '" + key + "'");
    }
  }
  if (t.compile.empty() || t.link.empty() || t.nm.empty())
    throw std::runtime_error(path + ": compile=, link= and nm= are required");
  const std::string identity = own_identity();
  t.fingerprint = Sha256()
                      .add(std::to_string(all.size()) + "\n" + all)
                      .add(std::to_string(identity.size()) + "\n" + identity)
                      .add(headers_state(t.headers))
                      .hex();
  return t;
}

std::vector<std::string> Toolchain::nm_command() const {
  if (nm_plugin.empty()) return {nm};
  return {nm, "--plugin", nm_plugin};
}

}  // namespace opspace::grading
