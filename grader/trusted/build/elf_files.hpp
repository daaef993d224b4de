/// @file elf_files.hpp
/// What the grader reads of the ELF files a runner's build makes from a student's file, every
/// offset and size checked against the file's own size (they are hostile input):
/// - an object file is a plain relocatable object and carries no compiler's bytecode (GCC's LTO
///   sections, which the linker plugin would compile and assemble in the link stage, where the
///   library's archive is in view: an .incbin there would embed it);
/// - the files a runner needs to start, and nothing more: its loader (the ELF's PT_INTERP) and
///   the shared libraries it names (DT_NEEDED), with theirs, found where the loader looks. The
///   sandbox shows a runner only these besides its own folder (SandboxSpec::runner).
#pragma once

#include <string>
#include <vector>

namespace opspace::grading {

/// Why `object` may not be linked (not a 64-bit ELF relocatable object; a section of LTO
/// bytecode, named), or empty. Throws std::runtime_error if it cannot be read.
std::string object_refusal(const std::string& object);

/// The loader and the shared libraries that `binary` (an ELF executable) needs, as absolute
/// paths. Throws std::runtime_error naming what is wrong (not an ELF, a library that cannot be
/// found, a name with a slash).
std::vector<std::string> runtime_files(const std::string& binary);

}  // namespace opspace::grading
