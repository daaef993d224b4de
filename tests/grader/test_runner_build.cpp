// nm's symbol lists of a runner's build (grader/trusted/runner_build.hpp, list_symbols): a list
// over the grader's bound is the submission's doing and says so, naming the file and the sizes;
// nm that cannot be started is the grader's. nm runs outside the sandbox here (isolate off): what
// is tested is who is blamed, not the sandbox.
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "runner_build.hpp"

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
  grading::SymbolList list(const std::string& nm, const std::string& file, std::size_t max_size) const {
    return grading::list_symbols(nm, "--defined-only", file, work, settings, "exercises/p1a.cpp",
                                 "the names its runner holds", max_size);
  }
};

}  // namespace

TEST_CASE("a symbol list within the bound is read whole") {
  const NmFixture f;
  const grading::SymbolList list = f.list(OPSPACE_NM, f.program, grading::kMaxSymbolList);
  CHECK(list.fault == grading::Fault::none);
  CHECK(list.error.empty());
  CHECK(list.names.size() > 100);
}

TEST_CASE("a symbol list over the bound is the submission's, naming the file and the sizes") {
  // Seen to fail on the grader before: "the grader could not list what the runner of
  // exercises/p1a.cpp holds", counted as the grader's fault.
  const NmFixture f;
  const grading::SymbolList list = f.list(OPSPACE_NM, f.program, 4096);
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
  const grading::SymbolList unreadable = f.list(OPSPACE_NM, text, grading::kMaxSymbolList);
  CHECK(unreadable.fault == grading::Fault::submission);
  CHECK(unreadable.error.rfind("exercises/p1a.cpp: nm could not list the names its runner holds (nm exited with code ", 0) == 0);
  const grading::SymbolList no_nm = f.list("/nonexistent/nm", f.program, grading::kMaxSymbolList);
  CHECK(no_nm.fault == grading::Fault::grader);
  CHECK(no_nm.error.rfind("the grader could not run nm on exercises/p1a.cpp: ", 0) == 0);
}
