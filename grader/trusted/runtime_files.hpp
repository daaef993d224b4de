/// @file runtime_files.hpp
/// The files a runner needs to start, and nothing more: its loader (the ELF's PT_INTERP) and the
/// shared libraries it names (DT_NEEDED), with theirs, found where the loader looks. The
/// sandbox shows a runner only these besides its own folder (sandbox.hpp: SandboxSpec::runner):
/// no compiler, no other program, no library archive.
#pragma once

#include <string>
#include <vector>

namespace opspace::grading {

/// The loader and the shared libraries that `binary` (an ELF executable, read as hostile input:
/// every offset and size is checked) needs, as absolute paths. Throws std::runtime_error naming
/// what is wrong (not an ELF, a library that cannot be found, a name with a slash).
std::vector<std::string> runtime_files(const std::string& binary);

}  // namespace opspace::grading
