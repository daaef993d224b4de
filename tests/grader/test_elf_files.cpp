// What the grader reads of a runner build's ELF files (grader/trusted/build/elf_files.hpp), as hostile
// input: a real program's loader and libraries are found; a file cut short, an offset past its
// end or a library name with a slash is refused with the reason, never read past its end; an
// object carrying LTO bytecode is refused before the link.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "build/elf_files.hpp"

namespace {

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Writes `bytes` to a file of its own and returns its path.
std::string write(const std::string& bytes, const char* name) {
  const std::string path = std::string("/tmp/opspace-test-runtime-") + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

std::string refusal(const std::string& path) {
  try {
    opspace::grading::runtime_files(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

bool ends_with(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

TEST_CASE("a dynamically linked program needs its loader and the C library, found where the loader looks") {
  // /usr/bin/true is part of coreutils, linked against glibc: its ELF names the loader
  // (PT_INTERP) and libc.so.6 (DT_NEEDED).
  const auto files = opspace::grading::runtime_files("/usr/bin/true");
  REQUIRE(!files.empty());
  CHECK_MESSAGE(files[0].find("ld-linux") != std::string::npos, "the loader comes first: " << files[0]);
  CHECK_MESSAGE(std::any_of(files.begin(), files.end(), [](const std::string& f) { return ends_with(f, "/libc.so.6"); }),
                "libc.so.6 must be among the files");
  for (const std::string& f : files) CHECK_MESSAGE(f[0] == '/', "an absolute path: " << f);
}

TEST_CASE("an ELF cut short, pointing past its end or naming a library by a path is refused, not read past its end") {
  const std::string program = read("/usr/bin/true");
  REQUIRE(program.size() > 4096);
  CHECK(refusal(write("not an ELF file", "text")).find("not a 64-bit ELF") != std::string::npos);
  // The ELF header alone (64 bytes): its program headers lie past the end.
  CHECK(refusal(write(program.substr(0, 64), "cut")).find("out of the file") != std::string::npos);
  // e_phoff (bytes 32-39) pointing far past the end.
  std::string far = program;
  for (int i = 32; i < 40; ++i) far[static_cast<std::size_t>(i)] = '\x7f';
  CHECK(refusal(write(far, "far")).find("out of the file") != std::string::npos);
  // "libc.so.6" in the string table made "/ibc.so.6": a path, which the loader would open as is.
  std::string slash = program;
  const std::size_t at = slash.find(std::string("libc.so.6\0", 10));
  REQUIRE(at != std::string::npos);
  slash[at] = '/';
  CHECK(refusal(write(slash, "slash")).find("not a plain file name") != std::string::npos);
  for (const char* name : {"text", "cut", "far", "slash"}) std::remove((std::string("/tmp/opspace-test-runtime-") + name).c_str());
}

TEST_CASE("an object carrying GCC's LTO bytecode is refused, a plain object is linked, a program is no object") {
  // The grader compiles an exercise without -flto: an object with .gnu.lto_ sections was made
  // to be compiled again by the linker's plugin, in the link stage (docs/grader.md).
  const std::string source = write("int answer() { return 42; }\n", "object.cpp");
  const std::string plain = "/tmp/opspace-test-runtime-plain.o", lto = "/tmp/opspace-test-runtime-lto.o";
  REQUIRE(std::system(("c++ -x c++ -c " + source + " -o " + plain).c_str()) == 0);
  REQUIRE(std::system(("c++ -x c++ -flto -c " + source + " -o " + lto).c_str()) == 0);
  CHECK_MESSAGE(opspace::grading::object_refusal(plain).empty(), "a plain object must be accepted");
  CHECK_MESSAGE(opspace::grading::object_refusal(lto).find("compiler bytecode (section .gnu.lto_") != std::string::npos,
                "an LTO object must be refused, naming its section");
  CHECK(opspace::grading::object_refusal("/usr/bin/true") == "not a relocatable object file");
  for (const std::string& f : {source, plain, lto}) std::remove(f.c_str());
}
