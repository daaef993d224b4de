#include "common/student_text.hpp"

#include <cstdio>

namespace opspace::grading {

namespace {

// The length of the valid UTF-8 sequence starting at s[i] and its code point (RFC 3629: no
// overlong forms, no surrogates, nothing above U+10FFFF); 0 if it is not one.
std::size_t decode(const std::string& s, std::size_t i, char32_t& cp) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b0 = byte(i);
  std::size_t n = 0;
  if (b0 < 0x80) {
    cp = b0;
    return 1;
  }
  if (b0 >= 0xc2 && b0 <= 0xdf) n = 2, cp = b0 & 0x1f;
  else if (b0 >= 0xe0 && b0 <= 0xef) n = 3, cp = b0 & 0x0f;
  else if (b0 >= 0xf0 && b0 <= 0xf4) n = 4, cp = b0 & 0x07;
  else return 0;
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3f);
  }
  const bool overlong = (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000);
  if (overlong || (cp >= 0xd800 && cp <= 0xdfff) || cp > 0x10ffff) return 0;
  return n;
}

// Code points that reorder, break or hide the text around them.
bool unsafe(char32_t cp) {
  return (cp >= 0x80 && cp <= 0x9f) || cp == 0x61c || cp == 0x200e || cp == 0x200f || (cp >= 0x202a && cp <= 0x202e) ||
         (cp >= 0x2066 && cp <= 0x2069) || cp == 0x2028 || cp == 0x2029;
}

std::string hex(const char* format, unsigned value) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

std::string cut_note(std::size_t shown, std::size_t total) {
  return total > shown ? "[... " + std::to_string(total - shown) + " more bytes not shown]" : "";
}

}  // namespace

std::string escape_student_text(const std::string& text, bool keep_newlines, bool in_quotes) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    char32_t cp = 0;
    const std::size_t n = decode(text, i, cp);
    if (n == 0) {
      out += hex("\\x%02x", static_cast<unsigned char>(text[i]));
      ++i;
      continue;
    }
    if (cp == '\n') out += keep_newlines ? "\n" : "\\n";
    else if (cp == '\t') out += "\\t";
    else if (in_quotes && (cp == '\\' || cp == '"')) out += "\\" + std::string(1, static_cast<char>(cp));
    else if (cp < 0x20 || cp == 0x7f) out += hex("\\x%02x", static_cast<unsigned>(cp));
    else if (unsafe(cp)) out += hex("\\u%04x", static_cast<unsigned>(cp));
    else out.append(text, i, n);
    i += n;
  }
  return out;
}

std::string student_line(const std::string& text, std::size_t limit, std::size_t total) {
  const std::string shown = text.substr(0, limit);
  const std::string note = cut_note(shown.size(), total);
  return "\"" + escape_student_text(shown, false, true) + "\"" + (note.empty() ? "" : " " + note);
}

std::string student_block(const std::string& text, std::size_t limit, std::size_t total) {
  const std::string shown = text.substr(0, limit);
  const std::string note = cut_note(shown.size(), total);
  return escape_student_text(shown, true, false) + (note.empty() ? "" : "\n" + note);
}

std::string quote_block(const std::string& block, const std::string& indent) {
  std::string out;
  std::size_t start = 0;
  std::size_t end = block.size();
  while (end > 0 && block[end - 1] == '\n') --end;
  while (start <= end) {
    std::size_t stop = block.find('\n', start);
    if (stop == std::string::npos || stop > end) stop = end;
    out += indent + "| " + block.substr(start, stop - start) + "\n";
    start = stop + 1;
  }
  return out;
}

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace opspace::grading
