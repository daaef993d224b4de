#include "runner_build.hpp"

#include <fcntl.h>
#include <poll.h>
#include <pwd.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "interrupt.hpp"
#include "library_answers.hpp"
#include "runner_process.hpp"
#include "sandbox.hpp"
#include "sha256.hpp"
#include "student_text.hpp"

namespace opspace::grading {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxSource = 1u << 20;     // an exercise file is a few kilobytes
constexpr std::size_t kMaxToolOutput = 1u << 16;  // what is kept of the compiler's output
constexpr std::size_t kMaxWarnings = 1500;        // what the report shows of the warnings
constexpr std::size_t kMaxSymbolList = 64u << 20;  // nm of a runner: 5-15 kB (--gc-sections)

struct CommandResult {
  bool timed_out = false;
  int status = 0;
  std::string output;  // stdout and stderr, at most the limit given to run_tool
  bool cut = false;    // the output was longer than that
};

// Runs argv in the sandbox (work_dir writable), with a time limit, capturing its output.
CommandResult run_tool(const std::vector<std::string>& argv, const std::string& work_dir,
                       const std::vector<std::string>& visible, const BuildSettings& settings,
                       std::size_t max_output = kMaxToolOutput) {
  int out[2];
  if (pipe2(out, O_CLOEXEC) != 0) throw std::runtime_error("the grader could not create a pipe");
  SandboxSpec spec;
  spec.argv = argv;
  spec.env = {"PATH=/usr/bin:/bin", "LANG=C", "LC_ALL=C", "TMPDIR=/tmp"};
  spec.work_dir = work_dir;
  spec.work_dir_writable = true;
  spec.visible = visible;
  spec.user = settings.user;
  spec.isolate = settings.isolate;
  // A compiler on one exercise file: well under 2 GiB and a minute on a laptop; a template
  // explosion in a student's file stops at these.
  spec.limits.address_space = 4ull << 30;
  spec.limits.cpu_seconds = static_cast<unsigned long long>(settings.timeout);
  spec.limits.file_size = 256ull << 20;
  spec.limits.open_files = 256;
  // No process limit: RLIMIT_NPROC counts every process of the sandbox user, so a runner's fork
  // flood in a concurrent grading (regrade --jobs) would make this compiler unable to start
  // cc1plus. The compiler forks a fixed few processes whatever the file says.
  spec.limits.processes = 0;
  const int null_in = open("/dev/null", O_RDONLY | O_CLOEXEC);
  spec.fds = {{0, null_in}, {1, out[1]}, {2, out[1]}};
  Sandboxed program;
  try {
    program = spawn(spec);
  } catch (...) {
    close(out[0]), close(out[1]), close(null_in);
    throw;
  }
  close(out[1]);
  close(null_in);
  CommandResult result;
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(settings.timeout));
  char buffer[4096];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      result.timed_out = true;
      break;
    }
    pollfd p{out[0], POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    const ssize_t n = read(out[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    const std::size_t room = max_output - result.output.size();
    result.cut = result.cut || static_cast<std::size_t>(n) > room;
    result.output.append(buffer, std::min<std::size_t>(static_cast<std::size_t>(n), room));
  }
  close(out[0]);
  if (result.timed_out || !wait_until(program, deadline, result.status)) {
    result.timed_out = true;
    result.status = kill_all(program);
  }
  return result;
}

std::string read_file(const std::string& path, std::size_t limit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string text;
  text.resize(limit + 1);
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

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

// The compiler's first error, "p1b.cpp:12:5: error: ...", and the source line below it, with
// the work folder's name of the file replaced by the name the student knows, as a grader line
// and the compiler's own lines quoted below it (student_text.hpp: they quote the student's
// code). Errors located in other files are shown only if those files are public headers (an
// include root). Empty if the output holds no error.
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
    if (in_student_file && i + 1 < all.size() && !all[i + 1].empty() && all[i + 1][0] == ' ') shown += "\n" + all[i + 1];
    return shown_as + ": the " + tool + "'s first error:\n" + student_block(shown, 600, shown.size());
  }
  return "";
}

std::string warnings_of(const std::string& output, const std::string& work_file, const std::string& shown_as) {
  std::string out;
  for (const std::string& line : lines(output)) {
    if (line.find(" warning: ") == std::string::npos) continue;
    out += replace_all(line, work_file, shown_as) + "\n";
  }
  return out.empty() ? out : student_block(out, kMaxWarnings, out.size());
}

// The files a compilation read, from its dependency file (make syntax: "target: dep dep \").
std::vector<std::string> dependencies(const std::string& depfile) {
  std::string text = read_file(depfile, 4u << 20);
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

// Every file the compilation read must be the student's own file or a public header.
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

void make_owned(const std::string& path, const std::string& user) {
  if (user.empty() || geteuid() != 0) return;
  const passwd* pw = getpwnam(user.c_str());
  if (!pw || chown(path.c_str(), pw->pw_uid, pw->pw_gid) != 0)
    throw std::runtime_error("cannot give the build folder to user " + user);
}

// The library's headers and archives, copied into the build folder (2 MB): the compiler then
// needs to see nothing of the repository, whatever the sandbox could hide or not (a chroot
// without namespaces, a repository under a folder the sandbox user cannot enter). Files are
// hard-linked where the file system allows it (the precompiled Eigen is 95 MB), copied otherwise;
// a link is as read-only to the sandbox user as the grader's file it links to.
struct Staged {
  std::vector<std::pair<std::string, std::string>> map;  // original path -> its copy
  std::string rewrite(std::string arg) const {
    for (const auto& [from, to] : map) {
      const std::size_t at = arg.find(from);
      if (at != std::string::npos) return arg.replace(at, from.size(), to);
    }
    return arg;
  }
};

Staged stage(const Toolchain& toolchain, const std::string& work) {
  Staged staged;
  std::vector<std::string> paths = toolchain.visible;
  std::sort(paths.begin(), paths.end(), [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const fs::path from(paths[i]);
    const fs::path dir = fs::path(work) / "kit" / std::to_string(i);
    fs::create_directories(dir);
    const fs::path to = fs::is_directory(from) ? dir : dir / from.filename();
    std::error_code linked;
    fs::copy(from, to, fs::copy_options::recursive | fs::copy_options::create_hard_links, linked);
    if (linked) {
      fs::remove_all(dir);
      fs::create_directories(dir);
      fs::copy(from, to, fs::copy_options::recursive);
    }
    staged.map.emplace_back(paths[i], to.string());
  }
  return staged;
}

const std::vector<std::string>* inputs_of(const Toolchain& toolchain, const std::string& key) {
  for (const auto& [k, inputs] : toolchain.inputs)
    if (k == key) return &inputs;
  return nullptr;
}

// Temporary names are the process's own: graders running at once (scripts/regrade) may build
// the same runner, and each renames only a file it wrote whole.
std::string temporary(const std::string& path) { return path + ".tmp" + std::to_string(getpid()); }

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

// Saves and restores what a cached build reported besides its binary.
void save_report(const std::string& path, const BuiltRunner& built) {
  const std::string tmp = temporary(path);
  std::ofstream out(tmp);
  out << built.warnings.size() << "\n" << built.warnings << "\n";
  for (const std::string& answer : built.answers) out << answer << "\n";
  out.close();
  fs::rename(tmp, path);
}

bool load_report(const std::string& path, BuiltRunner& built) {
  std::ifstream in(path);
  std::size_t size = 0;
  if (!(in >> size) || size > kMaxWarnings + 200) return false;
  in.get();
  built.warnings.resize(size);
  in.read(built.warnings.data(), static_cast<std::streamsize>(size));
  in.get();
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) built.answers.push_back(line);
  return true;
}

// The oracles of problem `key` that the answers found belong to.
void match_oracles(const std::string& key, BuiltRunner& built) {
  for (const Oracle& oracle : oracles(key)) {
    const bool found = std::any_of(built.answers.begin(), built.answers.end(),
                                   [&](const std::string& owner) { return belongs_to(owner, oracle); });
    if (found) built.called.push_back(oracle);
  }
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
    else if (key == "visible") t.visible.push_back(value);
    else if (key == "nm") t.nm = value;
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
  t.fingerprint = Sha256().add(std::to_string(all.size()) + "\n" + all).add(own_identity()).hex();
  return t;
}

BuiltRunner build_runner(const Toolchain& toolchain, const std::string& key, const std::string& source,
                         const std::string& shown_as, const BuildSettings& settings) {
  BuiltRunner built;
  const std::vector<std::string>* inputs = inputs_of(toolchain, key);
  if (!inputs) throw std::runtime_error("the runner toolchain has no inputs for problem " + key);
  std::string text;
  try {
    text = read_file(source, kMaxSource);
  } catch (const std::exception&) {
    built.error = shown_as + ": cannot read the file";
    return built;
  }
  if (text.size() > kMaxSource) {
    built.error = shown_as + ": larger than " + std::to_string(kMaxSource >> 10) + " KiB; an exercise file is a few";
    return built;
  }

  // The cache: same grader and toolchain, same libraries, same file -> same runner. The file
  // comes last, after its length, so that no two sets of fields give the same bytes.
  Sha256 hash;
  hash.add(toolchain.fingerprint + "\n" + key + "\n");
  for (const std::string& input : *inputs) {
    std::error_code ec;
    const auto time = fs::last_write_time(input, ec).time_since_epoch().count();
    hash.add(input + "\n" + std::to_string(time) + "\n");
  }
  hash.add(std::to_string(text.size()) + "\n" + text);
  const std::string cached = settings.cache_dir + "/runner-" + key + "-" + hash.hex();
  fs::create_directories(settings.cache_dir);
  if (fs::exists(cached) && load_report(cached + ".report", built)) {
    built.ok = true;
    built.cached = true;
    built.binary = cached;
    match_oracles(key, built);
    return built;
  }

  const TemporaryFolder folder("/tmp/opspace-build-");
  const std::string& work = folder.path();
  const std::string file = fs::path(shown_as).filename().string();
  const std::string work_file = work + "/" + file;
  std::ofstream(work_file, std::ios::binary) << text;
  const Staged staged = stage(toolchain, work);
  make_owned(work, settings.user);
  make_owned(work_file, settings.user);
  std::vector<std::string> roots;
  for (const std::string& root : toolchain.include_roots) roots.push_back(staged.rewrite(root));

  // Compile.
  std::vector<std::string> compile;
  for (const std::string& arg : toolchain.compile) compile.push_back(staged.rewrite(arg));
  compile.insert(compile.end(), {"-c", work_file, "-o", work + "/exercise.o", "-MD", "-MF", work + "/exercise.d"});
  const CommandResult cc = run_tool(compile, work, {}, settings);
  built.warnings = warnings_of(cc.output, work_file, shown_as);
  if (cc.timed_out) {
    built.error = "compiling " + shown_as + " took more than " + std::to_string(static_cast<int>(settings.timeout)) + " s";
    return built;
  }
  if (!WIFEXITED(cc.status) || WEXITSTATUS(cc.status) != 0) {
    built.error = first_error(cc.output, work_file, shown_as, roots, "compiler");
    if (built.error.empty()) built.error = "the compiler failed on " + shown_as + " (" + describe_wait_status(cc.status) + ")";
    return built;
  }
  built.error = check_includes(work + "/exercise.d", work, shown_as, roots);
  if (!built.error.empty()) return built;

  // The answers the file refers to, by any kind of reference ("U", or "w" and "v" for a weak or
  // aliased declaration, which pull nothing into the link but name what the file reaches for).
  const CommandResult refs = run_tool({toolchain.nm, "-C", "-P", "--undefined-only", work + "/exercise.o"}, work, {},
                                      settings, kMaxSymbolList);
  if (refs.timed_out || !WIFEXITED(refs.status) || WEXITSTATUS(refs.status) != 0 || refs.cut) {
    built.error = "the grader could not list the functions " + shown_as + " refers to";
    return built;
  }
  built.answers = answers_among(key, symbol_names(refs.output));

  // Link with the problem's runner loop and the library.
  std::vector<std::string> link = toolchain.link;
  link.push_back(work + "/exercise.o");
  for (const std::string& input : *inputs) link.push_back(staged.rewrite(input));
  link.insert(link.end(), {"-o", work + "/runner"});
  const CommandResult ld = run_tool(link, work, {}, settings);
  if (ld.timed_out || !WIFEXITED(ld.status) || WEXITSTATUS(ld.status) != 0) {
    built.error = first_error(ld.output, work + "/exercise.o", shown_as, roots, "linker");
    if (built.error.empty()) built.error = "linking the runner of " + shown_as + " failed";
    built.error = "linking failed: " + built.error;
    return built;
  }
  // What the runner holds of the library's answers, by whatever route they came in: its own
  // symbols (library_answers.hpp). nm's output is kept whole or not at all: a cut list could
  // hide an answer, so a runner whose list is too long is refused.
  const CommandResult nm = run_tool({toolchain.nm, "-C", "-P", "--defined-only", work + "/runner"}, work, {}, settings,
                                    kMaxSymbolList);
  if (nm.timed_out || !WIFEXITED(nm.status) || WEXITSTATUS(nm.status) != 0 || nm.cut) {
    built.error = "the grader could not list what the runner of " + shown_as + " holds";
    return built;
  }
  for (const std::string& answer : answers_among(key, symbol_names(nm.output)))
    if (std::find(built.answers.begin(), built.answers.end(), answer) == built.answers.end()) built.answers.push_back(answer);
  match_oracles(key, built);
  const std::string tmp = temporary(cached);
  fs::copy_file(work + "/runner", tmp, fs::copy_options::overwrite_existing);
  fs::permissions(tmp, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                           fs::perms::others_read | fs::perms::others_exec);
  fs::rename(tmp, cached);
  save_report(cached + ".report", built);
  built.ok = true;
  built.binary = cached;
  return built;
}

}  // namespace opspace::grading
