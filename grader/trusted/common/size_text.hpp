/// @file size_text.hpp
/// A number of bytes in words, as every message of the grader writes it (the report's bounds,
/// the runners' cache's line).
#pragma once

#include <string>

namespace opspace::grading {

/// "64 MiB", "64.1 MiB", "12 KiB", "900 bytes": rounded up to a tenth, so that a size over a
/// bound never reads as the bound.
std::string size_text(unsigned long long bytes);

}  // namespace opspace::grading
