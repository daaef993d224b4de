// The ELF files of a runner's build (elf_files.hpp), read as data: the object was compiled from
// a student's file and the runner linked from it, so every header is checked against the file's
// size before any use. The system's libraries, found by name in the loader's folders, are read
// the same way.
#include "build/elf_files.hpp"

#include <elf.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <set>
#include <stdexcept>

#include "build/compiler_messages.hpp"
#include "common/student_text.hpp"

namespace opspace::grading {

namespace {

constexpr std::size_t kMaxElf = 512u << 20;  // a runner is a few MB; libasan is 8 MB

struct ElfNames {
  std::string interpreter;
  std::vector<std::string> needed;
};

template <typename T>
bool read_at(const std::string& data, std::uint64_t offset, T& out) {
  if (offset > data.size() || data.size() - offset < sizeof(T)) return false;
  std::memcpy(&out, data.data() + offset, sizeof(T));
  return true;
}

// The NUL-terminated string at `offset` of `data`, within `limit` bytes; empty if none.
std::string string_at(const std::string& data, std::uint64_t offset, std::uint64_t limit) {
  if (offset >= data.size()) return "";
  const std::uint64_t room = std::min<std::uint64_t>(limit, data.size() - offset);
  const char* start = data.data() + offset;
  const void* end = std::memchr(start, '\0', room);
  return end ? std::string(start, static_cast<const char*>(end)) : "";
}

Elf64_Ehdr read_header(const std::string& data, const std::string& path) {
  Elf64_Ehdr header{};
  if (!read_at(data, 0, header) || std::memcmp(header.e_ident, ELFMAG, SELFMAG) != 0 ||
      header.e_ident[EI_CLASS] != ELFCLASS64)
    throw std::runtime_error(path + ": not a 64-bit ELF file");
  return header;
}

// The names of the sections of an ELF file.
std::vector<std::string> section_names(const std::string& data, const Elf64_Ehdr& header, const std::string& path) {
  const auto bad = [&](const std::string& why) { return std::runtime_error(path + ": " + why); };
  if (header.e_shnum == 0) return {};
  if (header.e_shentsize != sizeof(Elf64_Shdr)) throw bad("unexpected section header size");
  std::vector<Elf64_Shdr> sections(header.e_shnum);
  for (std::size_t i = 0; i < sections.size(); ++i)
    if (!read_at(data, header.e_shoff + i * sizeof(Elf64_Shdr), sections[i])) throw bad("section header out of the file");
  if (header.e_shstrndx >= sections.size()) throw bad("no table of section names");
  const Elf64_Shdr& names = sections[header.e_shstrndx];
  std::vector<std::string> out;
  for (const Elf64_Shdr& section : sections) {
    if (section.sh_name >= names.sh_size) throw bad("a section name out of its table");
    out.push_back(string_at(data, names.sh_offset + section.sh_name, names.sh_size - section.sh_name));
  }
  return out;
}

ElfNames read_elf(const std::string& path) {
  const std::string data = read_at_most(path, kMaxElf);
  const auto bad = [&](const std::string& why) { return std::runtime_error(path + ": " + why); };
  const Elf64_Ehdr header = read_header(data, path);
  if (header.e_phentsize != sizeof(Elf64_Phdr)) throw bad("unexpected program header size");
  std::vector<Elf64_Phdr> segments(header.e_phnum);
  for (std::size_t i = 0; i < segments.size(); ++i)
    if (!read_at(data, header.e_phoff + i * sizeof(Elf64_Phdr), segments[i])) throw bad("program header out of the file");
  // A virtual address to its offset in the file, through the loaded segment that holds it.
  const auto offset_of = [&](std::uint64_t address, std::uint64_t& offset) {
    for (const Elf64_Phdr& s : segments)
      if (s.p_type == PT_LOAD && address >= s.p_vaddr && address - s.p_vaddr < s.p_filesz) {
        offset = s.p_offset + (address - s.p_vaddr);
        return true;
      }
    return false;
  };
  ElfNames names;
  for (const Elf64_Phdr& s : segments) {
    if (s.p_type == PT_INTERP) names.interpreter = string_at(data, s.p_offset, s.p_filesz);
    if (s.p_type != PT_DYNAMIC) continue;
    std::vector<std::uint64_t> needed;
    std::uint64_t table = 0, table_size = 0;
    for (std::uint64_t at = 0; at + sizeof(Elf64_Dyn) <= s.p_filesz; at += sizeof(Elf64_Dyn)) {
      Elf64_Dyn entry{};
      if (!read_at(data, s.p_offset + at, entry)) throw bad("dynamic section out of the file");
      if (entry.d_tag == DT_NULL) break;
      if (entry.d_tag == DT_NEEDED) needed.push_back(entry.d_un.d_val);
      if (entry.d_tag == DT_STRTAB) table = entry.d_un.d_ptr;
      if (entry.d_tag == DT_STRSZ) table_size = entry.d_un.d_val;
    }
    std::uint64_t table_offset = 0;
    if (!needed.empty() && !offset_of(table, table_offset)) throw bad("string table out of the file");
    for (std::uint64_t name : needed) {
      if (name >= table_size) throw bad("a library name out of its table");
      names.needed.push_back(string_at(data, table_offset + name, table_size - name));
    }
  }
  return names;
}

// The folders the loader searches without its cache, in its order (ld.so --help lists them),
// those of this machine's architecture first.
std::vector<std::string> loader_folders() {
  std::vector<std::string> out;
  for (const char* triplet : {"x86_64-linux-gnu", "aarch64-linux-gnu"})
    for (const char* base : {"/lib/", "/usr/lib/"}) out.push_back(base + std::string(triplet));
  for (const char* dir : {"/lib64", "/usr/lib64", "/lib", "/usr/lib"}) out.emplace_back(dir);
  return out;
}

bool is_file(const std::string& path) {
  struct stat s {};
  return stat(path.c_str(), &s) == 0 && S_ISREG(s.st_mode);
}

}  // namespace

std::string object_refusal(const std::string& object) {
  const std::string data = read_at_most(object, kMaxElf);
  const Elf64_Ehdr header = read_header(data, object);
  if (header.e_type != ET_REL) return "not a relocatable object file";
  for (const std::string& name : section_names(data, header, object))
    if (name.rfind(".gnu.lto_", 0) == 0 || name.rfind(".gnu.debuglto_", 0) == 0)
      return "it carries compiler bytecode (section " + escape_student_text(name.substr(0, 60), false, false) +
             "), which the linker would compile: an exercise file is compiled by the grader alone";
  return "";
}

std::vector<std::string> runtime_files(const std::string& binary) {
  const ElfNames runner = read_elf(binary);
  std::vector<std::string> files;
  if (!runner.interpreter.empty()) {
    if (runner.interpreter[0] != '/' || !is_file(runner.interpreter))
      throw std::runtime_error(binary + ": its loader " + escape_student_text(runner.interpreter, false, false) + " is not a file");
    files.push_back(runner.interpreter);
  }
  std::vector<std::string> queue = runner.needed;
  std::set<std::string> seen;
  while (!queue.empty()) {
    const std::string name = queue.back();
    queue.pop_back();
    if (!seen.insert(name).second) continue;
    if (name.empty() || name.size() > 255 || name.find('/') != std::string::npos || name[0] == '.')
      throw std::runtime_error(binary + ": a library name that is not a plain file name: " +
                               escape_student_text(name, false, false));
    std::string found;
    for (const std::string& dir : loader_folders())
      if (is_file(dir + "/" + name)) {
        found = dir + "/" + name;
        break;
      }
    if (found.empty()) throw std::runtime_error(binary + ": needs " + escape_student_text(name, false, false) + ", found nowhere");
    files.push_back(found);
    for (const std::string& more : read_elf(found).needed) queue.push_back(more);
  }
  return files;
}

}  // namespace opspace::grading
