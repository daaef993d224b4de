// nm's symbol lists of a runner's build (grader/trusted/build/runner_build.hpp, list_symbols): a list
// over the grader's bound is the submission's doing and says so, naming the file and the sizes;
// nm that cannot be started is the grader's. And the tools the build's toolchain file chose:
// nm's plugin and the linker, each against what the compiler says here. nm runs outside the sandbox here (isolate off): what
// is tested is who is blamed, not the sandbox.
#include <doctest/doctest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "build/compiler_messages.hpp"
#include "build/runner_build.hpp"

namespace fs = std::filesystem;
namespace grading = opspace::grading;

namespace {

// A folder of its own for nm's work, and a program with thousands of symbols: this test.
struct NmFixture {
  std::string work = fs::temp_directory_path() / ("opspace-test-nm-" + std::to_string(::getpid()));
  std::string program = fs::read_symlink("/proc/self/exe").string();
  grading::BuildSettings settings;
  NmFixture() {
    fs::create_directories(work);
    settings.isolate = false;
    settings.timeout = 60.0;
  }
  ~NmFixture() { fs::remove_all(work); }
  grading::SymbolList list(const std::vector<std::string>& nm, const std::string& file, std::size_t max_size) const {
    return grading::list_symbols(nm, "--defined-only", file, work, settings, "exercises/p1a.cpp",
                                 "the names its runner holds", max_size);
  }
};

}  // namespace

TEST_CASE("a symbol list within the bound is read whole") {
  const NmFixture f;
  const grading::SymbolList list = f.list({OPSPACE_NM}, f.program, grading::kMaxSymbolList);
  CHECK(list.fault == grading::Fault::none);
  CHECK(list.error.empty());
  CHECK(list.names.size() > 100);
}

TEST_CASE("a symbol list over the bound is the submission's, naming the file and the sizes") {
  // Seen to fail on the grader before: "the grader could not list what the runner of
  // exercises/p1a.cpp holds", counted as the grader's fault.
  const NmFixture f;
  const grading::SymbolList list = f.list({OPSPACE_NM}, f.program, 4096);
  INFO(list.error);
  CHECK(list.fault == grading::Fault::submission);
  CHECK(list.names.empty());
  const std::string said = "exercises/p1a.cpp makes the symbol list over the 4 KiB the grader reads: nm listed ";
  CHECK(list.error.rfind(said, 0) == 0);
  CHECK(list.error.find(" KiB of the names its runner holds") != std::string::npos);
  CHECK(list.error.find("the grader could not") == std::string::npos);
}

TEST_CASE("nm failing on the file is the submission's, and nm that cannot start is the grader's") {
  const NmFixture f;
  const std::string text = f.work + "/not-an-object.o";
  std::ofstream(text) << "not an object\n";
  const grading::SymbolList unreadable = f.list({OPSPACE_NM}, text, grading::kMaxSymbolList);
  CHECK(unreadable.fault == grading::Fault::submission);
  CHECK(unreadable.error.rfind("exercises/p1a.cpp: nm could not list the names its runner holds (nm exited with code ", 0) == 0);
  const grading::SymbolList no_nm = f.list({"/nonexistent/nm"}, f.program, grading::kMaxSymbolList);
  CHECK(no_nm.fault == grading::Fault::grader);
  CHECK(no_nm.error.rfind("the grader could not run nm on exercises/p1a.cpp: ", 0) == 0);
}

namespace {

// What `command` prints, its last newline cut.
std::string output_of(const std::string& command) {
  std::string out;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
    pclose(pipe);
  }
  if (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

}  // namespace

TEST_CASE("nm is told the compiler's own LTO plugin where the compiler has one, and lists the same symbols") {
  // Asked of the compiler here, apart from the configure step that wrote the toolchain: where
  // gcc names its liblto_plugin.so (an absolute path that exists), nm loads it alone instead of
  // every plugin of bfd-plugins/ (clang's LLVMgold: 60 ms a list, issue 50).
  const grading::Toolchain toolchain = grading::load_toolchain(OPSPACE_RUNNER_TOOLCHAIN);
  const std::string named = output_of(std::string(OPSPACE_CXX) + " -print-file-name=liblto_plugin.so 2>/dev/null");
  const bool has_plugin = !named.empty() && named[0] == '/' && fs::exists(named);
  INFO("the compiler names: " << named);
  if (has_plugin) {
    CHECK(toolchain.nm_plugin == named);
    CHECK(toolchain.nm_command() == std::vector<std::string>{toolchain.nm, "--plugin", named});
  } else {
    CHECK(toolchain.nm_plugin.empty());
    CHECK(toolchain.nm_command() == std::vector<std::string>{toolchain.nm});
  }
  // The same list with the plugin as without: this test program's thousands of symbols.
  const NmFixture f;
  const grading::SymbolList plain = f.list({toolchain.nm}, f.program, grading::kMaxSymbolList);
  const grading::SymbolList told = f.list(toolchain.nm_command(), f.program, grading::kMaxSymbolList);
  CHECK(told.fault == grading::Fault::none);
  CHECK(plain.names.size() > 100);
  CHECK(told.names == plain.names);
}

TEST_CASE("the runner is linked by gold where the compiler links and runs a program with it") {
  // Asked of the compiler here: a program linked with -fuse-ld=gold that runs. Where it does,
  // the toolchain links runners with gold (0.05-0.08 s against bfd's 0.13 s, issue 50); where
  // it does not, with the compiler's default linker.
  const std::string work = fs::temp_directory_path() / ("opspace-test-gold-" + std::to_string(::getpid()));
  fs::create_directories(work);
  std::ofstream(work + "/main.cpp") << "int main() { return 0; }\n";
  const bool gold_works =
      output_of(std::string(OPSPACE_CXX) + " -fuse-ld=gold -Wl,--gc-sections " + work + "/main.cpp -o " + work +
                "/main >/dev/null 2>&1 && " + work + "/main && echo linked") == "linked";
  fs::remove_all(work);
  const grading::Toolchain toolchain = grading::load_toolchain(OPSPACE_RUNNER_TOOLCHAIN);
  const bool with_gold = std::find(toolchain.link.begin(), toolchain.link.end(), "-fuse-ld=gold") != toolchain.link.end();
  CHECK(with_gold == gold_works);
}

TEST_CASE("a toolchain file without nm-plugin runs nm as it is") {
  const std::string path = fs::temp_directory_path() / ("opspace-test-toolchain-" + std::to_string(::getpid()));
  std::ofstream(path) << "compile=c++\nlink=c++\nnm=/usr/bin/nm\nnm-plugin=\n";
  const grading::Toolchain bare = grading::load_toolchain(path);
  CHECK(bare.nm_command() == std::vector<std::string>{"/usr/bin/nm"});
  std::ofstream(path) << "compile=c++\nlink=c++\nnm=/usr/bin/nm\nnm-plugin=/usr/lib/x/liblto_plugin.so\n";
  CHECK(grading::load_toolchain(path).nm_command() ==
        std::vector<std::string>{"/usr/bin/nm", "--plugin", "/usr/lib/x/liblto_plugin.so"});
  fs::remove(path);
}

TEST_CASE("a header added, edited or removed under the toolchain's headers changes its fingerprint") {
  // The runner cache's key holds the fingerprint (runner_build.cpp, cache_key): a runner built
  // before a header was dropped beside the contracts by hand must not be served after it.
  const fs::path work = fs::temp_directory_path() / ("opspace-test-headers-" + std::to_string(::getpid()));
  fs::create_directories(work / "contracts/problems/1a");
  std::ofstream(work / "contracts/problems/1a/contract.hpp") << "#pragma once\n";
  const std::string path = (work / "toolchain.txt").string();
  std::ofstream(path) << "compile=c++\nlink=c++\nnm=/usr/bin/nm\nheaders=" << (work / "contracts").string() << "\n";
  const std::string before = grading::load_toolchain(path).fingerprint;
  CHECK(grading::load_toolchain(path).fingerprint == before);  // nothing changed: the same key

  std::ofstream(work / "contracts/problems/1a/tests.hpp") << "#pragma once\n";
  const std::string added = grading::load_toolchain(path).fingerprint;
  CHECK_MESSAGE(added != before, "a file added beside the contract must change the key");

  std::ofstream(work / "contracts/problems/1a/tests.hpp", std::ios::app) << "// edited\n";
  const std::string edited = grading::load_toolchain(path).fingerprint;
  CHECK_MESSAGE(edited != added, "a header whose size changed must change the key");

  fs::remove(work / "contracts/problems/1a/tests.hpp");
  CHECK_MESSAGE(grading::load_toolchain(path).fingerprint == before, "the folder as it was gives the key it gave");
  fs::remove_all(work);
}

// The compiler's first error (compiler_messages.hpp) is on the grader's line, quoted: the line
// each of the problem's tests carries. Before issue 58 that line ended in "first error:".
TEST_CASE("the compiler's first error is on the grader's line, the source line below it") {
  const std::string output =
      "/work/src/p1b.cpp:5:84: error: expected ',' or ';' before 'return'\n"
      "    5 |   Vector6d tau = Vector6d::Zero() return tau;\n";
  const std::string shown = grading::first_error(output, "/work/src/p1b.cpp", "exercises/p1b.cpp", {}, "compiler");
  CHECK(shown ==
        "exercises/p1b.cpp: the compiler's first error: \"exercises/p1b.cpp:5:84: error: expected ',' or ';' before "
        "'return'\"\n    5 |   Vector6d tau = Vector6d::Zero() return tau;");
}

// Each problem's contract by the path it had before commit 77461ea, as GCC and Clang say it:
// the student is told today's. Before issue 58: the compiler's words alone.
TEST_CASE("a contract included by its former path is named with today's, for every problem") {
  for (const std::string key : {"1a", "1b", "2", "3", "4"}) {
    CAPTURE(key);
    const std::string file = "/work/src/p" + key + ".cpp";
    const std::string told = "exercises/p" + key + ".cpp includes its contract by its former path: write #include <problems/" +
                             key + "/contract.hpp> instead of <opspace/hw2/p" + key + ".hpp>; the compiler's first error: ";
    const std::string gcc = file + ":2:10: fatal error: opspace/hw2/p" + key + ".hpp: No such file or directory\n";
    const std::string clang = file + ":2:10: fatal error: 'opspace/hw2/p" + key + ".hpp' file not found\n";
    for (const std::string& output : {gcc, clang}) {
      const std::string shown = grading::first_error(output, file, "exercises/p" + key + ".cpp", {}, "compiler");
      CHECK(shown.rfind(told, 0) == 0);
    }
  }
  // Another header not found is the compiler's error alone.
  const std::string other = grading::first_error("/work/src/p1b.cpp:2:10: fatal error: opspace/hw3/p1b.hpp: No such file or directory\n",
                                                 "/work/src/p1b.cpp", "exercises/p1b.cpp", {}, "compiler");
  CHECK(other.rfind("exercises/p1b.cpp: the compiler's first error: \"exercises/p1b.cpp:2:10: fatal error:", 0) == 0);
}
