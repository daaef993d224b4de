#include "build/runner_build.hpp"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <future>
#include <sstream>
#include <stdexcept>

#include "build/build_tool.hpp"
#include "build/compiler_messages.hpp"
#include "build/elf_files.hpp"
#include "sandbox/grading_group.hpp"
#include "common/temporary_folder.hpp"
#include "build/library_answers.hpp"
#include "build/runner_cache.hpp"
#include "sandbox/sandbox.hpp"
#include "common/sha256.hpp"
#include "common/size_text.hpp"
#include "common/student_text.hpp"

namespace opspace::grading {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxSource = 1u << 20;     // an exercise file is a few kilobytes
constexpr std::size_t kMaxToolOutput = 1u << 16;  // what is kept of the compiler's output
constexpr std::size_t kMaxWarnings = 1500;        // what the report shows of the warnings

// Records why the build stops and who caused it (fault.hpp). Returns false, the stage's result.
bool stop(BuiltRunner& built, Fault fault, std::string error) {
  built.fault = fault;
  built.error = std::move(error);
  return false;
}

void make_owned(const std::string& path, const Account& account) {
  if (account.uid == 0 || geteuid() != 0) return;
  if (chown(path.c_str(), account.uid, account.gid) != 0)
    throw std::runtime_error("cannot give a build folder to " + account.name);
}

// A folder of the build, made by the grader: for what the stage writes (its output, and nothing
// else), the sandbox's account's own (0700); for what it reads, the grader's, readable by the
// account's group alone (0750), so that no other grading's account reads this student's files
// even where the files' view is not private.
std::string make_folder(const std::string& path, bool writable, const Account& account) {
  fs::create_directories(path);
  fs::permissions(path, writable ? fs::perms::owner_all : fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec);
  if (writable) {
    make_owned(path, account);
  } else if (account.uid == 0 || geteuid() != 0) {
    fs::permissions(path, fs::perms::others_read | fs::perms::others_exec, fs::perm_options::add);
  } else if (chown(path.c_str(), 0, account.gid) != 0) {
    throw std::runtime_error("cannot give a build folder to " + account.name + "'s group");
  }
  return path;
}

// The library's headers or archives, copied into the build folder: the stage then needs to see
// nothing of the repository, whatever the sandbox could hide or not (a chroot without
// namespaces, a repository under a folder the sandbox's account cannot enter). Files are
// hard-linked where the file system allows it (the precompiled Eigen is 95 MB), copied otherwise;
// a link is as read-only to the sandbox's account as the grader's file it links to.
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

Staged stage(std::vector<std::string> paths, const std::string& kit) {
  Staged staged;
  std::sort(paths.begin(), paths.end(), [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const fs::path from(paths[i]);
    const fs::path dir = fs::path(kit) / std::to_string(i);
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

// A copy of `from` the grader owns, read-only to everyone: what the next stage reads is what the
// last one wrote, and nothing the sandbox's account can change since.
// A file a stage wrote, and no link: the grader reads it with its own rights, which must not
// follow a link to a file the stage could not see.
bool written_file(const std::string& path) {
  struct stat s {};
  return lstat(path.c_str(), &s) == 0 && S_ISREG(s.st_mode) && s.st_nlink == 1;
}

void copy_read_only(const std::string& from, const std::string& to) {
  if (!written_file(from)) throw std::runtime_error(from + " is not a file the stage wrote");
  fs::copy_file(from, to, fs::copy_options::overwrite_existing);
  fs::permissions(to, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
}

const std::vector<std::string>* inputs_of(const Toolchain& toolchain, const std::string& key) {
  for (const auto& [k, inputs] : toolchain.inputs)
    if (k == key) return &inputs;
  return nullptr;
}

// Temporary names are the process's own: graders running at once (scripts/regrade) may build
// the same runner, and each renames only a file it wrote whole.
std::string temporary(const std::string& path) { return path + ".tmp" + std::to_string(getpid()); }

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

// The library answers of problem `key` among the symbols of `list`, added to built.answers.
// False, with built.error, if the list could not be read whole (list_symbols).
bool add_answers(const std::string& key, const SymbolList& list, BuiltRunner& built) {
  if (list.fault != Fault::none) return stop(built, list.fault, list.error);
  for (const std::string& answer : answers_among(key, list.names))
    if (std::find(built.answers.begin(), built.answers.end(), answer) == built.answers.end()) built.answers.push_back(answer);
  return true;
}

// The cache: same grader and toolchain, same libraries, same file -> same runner. The file
// comes last, after its length, so that no two sets of fields give the same bytes.
std::string cache_key(const Toolchain& toolchain, const std::string& key, const std::vector<std::string>& inputs,
                      const std::string& text) {
  Sha256 hash;
  hash.add(toolchain.fingerprint + "\n" + key + "\n");
  for (const std::string& input : inputs) {
    std::error_code ec;
    const auto time = fs::last_write_time(input, ec).time_since_epoch().count();
    hash.add(input + "\n" + std::to_string(time) + "\n");
  }
  hash.add(std::to_string(text.size()) + "\n" + text);
  return hash.hex();
}

// The folders of one build, one per stage (docs/grader.md, "What each stage sees"). A stage
// reads folders the grader wrote, read-only to it, and writes only its own; the next stage reads
// the grader's copy of what it wrote. The source is `text`, the bytes the cache key was taken
// from, written by the grader.
struct Stages {
  std::string work, source, compiled, objects, linked, listed, headers_dir, archives_dir;
  std::string source_file, object, runner;
  Staged headers;
  std::vector<std::string> roots;  // the include roots, as the compiler sees them

  Stages(const std::string& folder, const std::string& shown_as, const std::string& text, const Toolchain& toolchain,
         const Account& account)
      : work(folder),
        source(make_folder(work + "/source", false, account)),
        compiled(make_folder(work + "/compiled", true, account)),
        objects(make_folder(work + "/objects", false, account)),
        linked(make_folder(work + "/linked", true, account)),
        listed(make_folder(work + "/listed", true, account)),
        headers_dir(make_folder(work + "/headers", false, account)),
        archives_dir(make_folder(work + "/archives", false, account)),
        source_file(source + "/" + fs::path(shown_as).filename().string()),
        object(objects + "/exercise.o"),
        runner(objects + "/runner") {
    fs::permissions(work, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
    std::ofstream(source_file, std::ios::binary) << text;
    fs::permissions(source_file, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    headers = stage(toolchain.headers, headers_dir);
    for (const std::string& root : toolchain.include_roots) roots.push_back(headers.rewrite(root));
  }
};

// Compiles the source: it sees the source and the headers, no archive of the library and no
// other file of this grading (an .incbin or #embed reaches only what this stage sees); checks
// what it included, and copies the object for the next stages. False with built.error.
bool compile_stage(const Toolchain& toolchain, const Stages& s, const std::string& shown_as,
                   const BuildSettings& settings, BuiltRunner& built) {
  std::vector<std::string> compile;
  for (const std::string& arg : toolchain.compile) compile.push_back(s.headers.rewrite(arg));
  compile.insert(compile.end(), {"-c", s.source_file, "-o", s.compiled + "/exercise.o", "-MD", "-MF", s.compiled + "/exercise.d"});
  const unsigned long long kills = grading_memory_kills();
  const ToolResult cc = run_tool(compile, s.compiled, {s.source, s.headers_dir}, settings, kMaxToolOutput);
  built.warnings = warnings_of(cc.output, s.source_file, shown_as, kMaxWarnings);
  if (cc.timed_out) {
    return stop(built, Fault::submission,
                "compiling " + shown_as + " took more than " + std::to_string(static_cast<int>(settings.timeout)) + " s");
  }
  const bool failed = !WIFEXITED(cc.status) || WEXITSTATUS(cc.status) != 0;
  if (failed && grading_memory_kills() > kills) {
    // The kernel stopped a compiler at the grading's budget (grading_group.hpp): one exercise
    // file compiles in about 270 MB (with the precompiled Eigen).
    return stop(built, Fault::submission,
                "compiling " + shown_as + " took more than this grading's memory budget of " +
                    size_text(grading_memory_group_budget()) + " (the kernel stopped the compiler)");
  }
  if (failed) {
    const std::string error = first_error(cc.output, s.source_file, shown_as, s.roots, "compiler");
    return stop(built, Fault::submission,
                error.empty() ? "the compiler failed on " + shown_as + " (" + describe_wait_status(cc.status) + ")" : error);
  }
  const std::string refused = written_file(s.compiled + "/exercise.d")
                                  ? check_includes(s.compiled + "/exercise.d", s.source, shown_as, s.roots)
                                  : "the compiler left no list of what " + shown_as + " included";
  if (!refused.empty()) return stop(built, Fault::submission, refused);
  if (!written_file(s.compiled + "/exercise.o"))
    return stop(built, Fault::submission, "the compiler left no object file for " + shown_as);
  std::string refusal;
  try {
    copy_read_only(s.compiled + "/exercise.o", s.object);
    refusal = object_refusal(s.object);
  } catch (const std::exception& e) {
    return stop(built, Fault::grader, "the grader could not read the object of " + shown_as + ": " + e.what());
  }
  if (!refusal.empty())
    return stop(built, Fault::submission, shown_as + " compiled to an object the grader does not link: " + refusal);
  return true;
}

// Links the grader's copy of the object with this problem's inputs (its runner loop and the
// library: the only archives it sees), copies the runner and reads what it needs to start.
bool link_stage(const Toolchain& toolchain, const std::vector<std::string>& inputs, const Stages& s,
                const std::string& shown_as, const BuildSettings& settings, BuiltRunner& built) {
  std::vector<std::string> own_archives;
  for (const std::string& archive : toolchain.archives)
    if (std::find(inputs.begin(), inputs.end(), archive) != inputs.end()) own_archives.push_back(archive);
  const Staged archives = stage(own_archives, s.archives_dir);
  std::vector<std::string> link = toolchain.link;
  link.push_back(s.object);
  for (const std::string& input : inputs) link.push_back(archives.rewrite(input));
  link.insert(link.end(), {"-o", s.linked + "/runner"});
  const ToolResult ld = run_tool(link, s.linked, {s.objects, s.archives_dir}, settings, kMaxToolOutput);
  if (ld.timed_out || !WIFEXITED(ld.status) || WEXITSTATUS(ld.status) != 0) {
    const std::string error = first_error(ld.output, s.object, shown_as, s.roots, "linker");
    return stop(built, Fault::submission,
                "linking failed: " + (error.empty() ? "linking the runner of " + shown_as + " failed" : error));
  }
  try {
    copy_read_only(s.linked + "/runner", s.runner);
    built.runtime = runtime_files(s.runner);
  } catch (const std::exception& e) {
    return stop(built, Fault::grader, std::string("the grader could not read the runner it linked: ") + e.what());
  }
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

SymbolList list_symbols(const std::vector<std::string>& nm, const std::string& which, const std::string& file,
                        const std::string& work, const BuildSettings& settings, const std::string& shown_as,
                        const std::string& what, std::size_t max_size) {
  SymbolList list;
  ToolResult run;
  try {
    std::vector<std::string> argv = nm;
    argv.insert(argv.end(), {"-C", "-P", which, file});
    run = run_tool(argv, work, {fs::path(file).parent_path().string()}, settings, max_size);
  } catch (const std::exception& e) {
    list.fault = Fault::grader;
    list.error = "the grader could not run nm on " + shown_as + ": " + e.what();
    return list;
  }
  // nm ran: what it made of the student's object (or the runner linked from it) is theirs.
  list.fault = Fault::submission;
  if (run.cut) {
    list.error = shown_as + " makes the symbol list over the " + size_text(max_size) + " the grader reads: nm listed " +
                 (run.timed_out ? "more than " : "") + size_text(run.total) + " of " + what +
                 ", where a file of a few functions lists a few KiB";
  } else if (run.timed_out) {
    list.error = shown_as + ": nm took more than " + std::to_string(static_cast<int>(settings.timeout)) + " s to list " + what;
  } else if (!WIFEXITED(run.status) || WEXITSTATUS(run.status) != 0) {
    list.error = shown_as + ": nm could not list " + what + " (nm " + describe_wait_status(run.status) + ")";
  } else {
    list.fault = Fault::none;
    list.names = symbol_names(run.output);
  }
  return list;
}

BuiltRunner build_runner(const Toolchain& toolchain, const std::string& key, const std::string& source,
                         const std::string& shown_as, const BuildSettings& settings) {
  BuiltRunner built;
  const std::vector<std::string>* inputs = inputs_of(toolchain, key);
  if (!inputs) throw std::runtime_error("the runner toolchain has no inputs for problem " + key);
  std::string text;
  try {
    text = read_at_most(source, kMaxSource);
  } catch (const std::exception&) {
    stop(built, Fault::submission, shown_as + ": cannot read the file");
    return built;
  }
  if (text.size() > kMaxSource) {
    stop(built, Fault::submission, shown_as + ": larger than " + size_text(kMaxSource) + "; an exercise file is a few KiB");
    return built;
  }

  // The cache is the grader's alone: no account of a sandbox reads or writes it.
  const std::string cached = settings.cache_dir + "/runner-" + key + "-" + cache_key(toolchain, key, *inputs, text);
  fs::create_directories(settings.cache_dir);
  fs::permissions(settings.cache_dir, fs::perms::owner_all);
  if (fs::exists(cached) && load_report(cached + ".report", built)) {
    built.ok = true;
    built.cached = true;
    match_oracles(key, built);
    try {
      built.binary = hold_runner(cached, settings.cache_dir, key);
      built.runtime = runtime_files(cached);
    } catch (const std::exception& e) {
      built = BuiltRunner{};
      stop(built, Fault::grader, std::string("the grader could not read its runner: ") + e.what());
    }
    return built;
  }

  const TemporaryFolder folder("/tmp/opspace-build-");
  const Stages stages(folder.path(), shown_as, text, toolchain, settings.account);
  if (!compile_stage(toolchain, stages, shown_as, settings, built)) return built;
  // The answers the file refers to, by any kind of reference ("U", or "w" and "v" for a weak or
  // aliased declaration, which pull nothing into the link but name what the file reaches for),
  // listed while the runner is linked (both read the grader's copy of the object; nm writes in
  // a folder of its own): nm and its sandbox's start leave an edit's path for the second core.
  // Its failure still comes first, whatever the link did.
  std::future<SymbolList> referred = std::async(std::launch::async, [&] {
    return list_symbols(toolchain.nm_command(), "--undefined-only", stages.object, stages.listed, settings, shown_as,
                        "the names it refers to");
  });
  const bool linked = link_stage(toolchain, *inputs, stages, shown_as, settings, built);
  const SymbolList referred_list = referred.get();
  if (referred_list.fault != Fault::none) {
    built.runtime.clear();  // as if the link had not run: its outcome is not this failure's
    stop(built, referred_list.fault, referred_list.error);
    return built;
  }
  if (!linked) return built;
  add_answers(key, referred_list, built);
  // What the runner holds of the library's answers, by whatever route they came in: its own
  // symbols (library_answers.hpp).
  if (!add_answers(key,
                   list_symbols(toolchain.nm_command(), "--defined-only", stages.runner, stages.linked, settings,
                                shown_as, "the names its runner holds"),
                   built))
    return built;
  match_oracles(key, built);
  const std::string tmp = temporary(cached);
  fs::copy_file(stages.runner, tmp, fs::copy_options::overwrite_existing);
  fs::permissions(tmp, fs::perms::owner_read | fs::perms::owner_exec);
  fs::rename(tmp, cached);
  save_report(cached + ".report", built);
  built.ok = true;
  built.binary = hold_runner(cached, settings.cache_dir, key);
  return built;
}

}  // namespace opspace::grading
