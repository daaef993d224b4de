// `printable`: text from a file made safe to put in an error message (the URDF loader,
// model_text.cpp).
#pragma once

#include <string>

namespace opspace::detail {

/// The two hexadecimal digits of `c`'s byte.
inline std::string hex(char c) {
  const char* digits = "0123456789abcdef";
  const auto byte = static_cast<unsigned char>(c);
  return {digits[byte >> 4], digits[byte & 15]};
}

/// `text` with its control characters written \xNN: names come from the file, and a message
/// must not drive the terminal it is printed on.
inline std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    out += byte < 0x20 || byte == 0x7f ? "\\x" + hex(c) : std::string(1, c);
  }
  return out;
}

}  // namespace opspace::detail
