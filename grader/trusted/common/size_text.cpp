#include "common/size_text.hpp"

#include <cmath>
#include <cstdio>

namespace opspace::grading {

std::string size_text(unsigned long long bytes) {
  const bool mib = bytes >= (1u << 20), kib = bytes >= (1u << 10);
  if (!mib && !kib) return std::to_string(bytes) + " bytes";
  const double tenths = std::ceil(static_cast<double>(bytes) / (mib ? 1u << 20 : 1u << 10) * 10.0);
  char text[32];
  std::snprintf(text, sizeof text, "%.*f %s", std::fmod(tenths, 10.0) == 0.0 ? 0 : 1, tenths / 10.0, mib ? "MiB" : "KiB");
  return text;
}

}  // namespace opspace::grading
