// Pass 0 of the URDF loader (urdf.cpp): scans of the text before any parser reads it. It must
// be UTF-8 without NUL bytes (TinyXML reads past the end of a cut UTF-8 sequence), and the
// markup's nesting depth and attributes per element are bounded (TinyXML recurses once per
// level and compares each new attribute with the element's others: the call stack or quadratic
// time would pay for them).
#include <algorithm>
#include <cstring>
#include <string>

#include "printable.hpp"
#include "urdf_passes.hpp"

namespace opspace::urdf_passes {

namespace {

using detail::hex;

/// Length of the well-formed UTF-8 character at xml[i] (Unicode, table 3-7: a lead byte, a
/// second byte in a range the lead sets, then bytes in 0x80-0xbf); 0 if it is malformed.
std::size_t utf8_length(const std::string& xml, std::size_t i) {
  const auto at = [&](std::size_t k) -> unsigned { return k < xml.size() ? static_cast<unsigned char>(xml[k]) : 0u; };
  const unsigned c = at(i);
  if (c < 0x80) return 1;
  std::size_t length = 0;
  unsigned low = 0x80, high = 0xbf;
  if (c >= 0xc2 && c <= 0xdf) {
    length = 2;
  } else if (c >= 0xe0 && c <= 0xef) {
    length = 3;
    low = c == 0xe0 ? 0xa0 : low;   // no overlong forms
    high = c == 0xed ? 0x9f : high;  // no surrogates
  } else if (c >= 0xf0 && c <= 0xf4) {
    length = 4;
    low = c == 0xf0 ? 0x90 : low;
    high = c == 0xf4 ? 0x8f : high;  // nothing above U+10FFFF
  } else {
    return 0;
  }
  if (at(i + 1) < low || at(i + 1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (at(i + k) < 0x80 || at(i + k) > 0xbf) return 0;
  }
  return length;
}

}  // namespace

/// Pass 0, first: the text is UTF-8 (what both parsers read it as) without NUL bytes (where
/// they would stop reading). TinyXML steps over a character by the length its first byte
/// announces, so a sequence cut short by the end of the text made it read past the end (found
/// by fuzz-urdf under AddressSanitizer).
void check_encoding(const std::string& xml, const std::string& source) {
  int line = 1;
  for (std::size_t i = 0; i < xml.size();) {
    const char c = xml[i];
    const std::size_t length = c == '\0' ? 0 : utf8_length(xml, i);
    if (length == 0) {
      fail(source, line, c == '\0' ? "a NUL byte: a URDF is text"
                                   : "malformed UTF-8 at byte 0x" + hex(c) + " (a URDF is UTF-8 text)");
    }
    if (c == '\n' || (c == '\r' && (i + 1 == xml.size() || xml[i + 1] != '\n'))) ++line;
    i += length;
  }
}

/// Pass 0's bounds: a URDF nests about 5 elements deep and gives one at most 6 attributes.
constexpr int kMaxDepth = 100;
constexpr int kMaxAttributes = 100;

/// Pass 0: walks the tags (comments, CDATA sections, declarations skipped; quoted attribute
/// values honoured) counting lines as TinyXML does ("\r\n", "\r" and "\n" end one), and
/// refuses an element nested deeper than kMaxDepth or with more than kMaxAttributes.
void check_markup(const std::string& xml, const std::string& source) {
  const std::size_t n = xml.size();
  std::size_t i = 0;
  int line = 1, depth = 0;
  const auto skip_to = [&](std::size_t end) {  // moves i to end (at most n), counting lines
    end = std::min(end, n);
    for (; i < end; ++i) {
      if (xml[i] == '\n' || (xml[i] == '\r' && (i + 1 == n || xml[i + 1] != '\n'))) ++line;
    }
  };
  const auto past = [&](const char* token, std::size_t from) {  // the end of the next `token`
    const std::size_t at = xml.find(token, from);
    return at == std::string::npos ? n : at + std::strlen(token);
  };
  while (i < n) {
    skip_to(xml.find('<', i));
    if (i >= n) break;
    if (xml.compare(i, 4, "<!--") == 0) {
      skip_to(past("-->", i + 4));
    } else if (xml.compare(i, 9, "<![CDATA[") == 0) {
      skip_to(past("]]>", i + 9));
    } else if (i + 1 < n && (xml[i + 1] == '?' || xml[i + 1] == '!' || xml[i + 1] == '/')) {
      if (xml[i + 1] == '/') depth = std::max(0, depth - 1);
      skip_to(past(">", i + 1));
    } else {  // a start tag, up to its '>' outside quotes
      const int row = line;
      int attributes = 0;
      std::size_t k = i + 1;
      for (; k < n && xml[k] != '>'; ++k) {
        if (xml[k] == '"' || xml[k] == '\'') {
          k = std::min(xml.find(xml[k], k + 1), n - 1);
        } else if (xml[k] == '=' && ++attributes > kMaxAttributes) {
          fail(source, row, "an element with more than " + std::to_string(kMaxAttributes) +
                                " attributes (a URDF element has at most 6)");
        }
      }
      if (k < n && xml[k - 1] != '/' && ++depth > kMaxDepth) {
        fail(source, row, "elements nested more than " + std::to_string(kMaxDepth) +
                              " deep (a URDF nests about 5)");
      }
      skip_to(k + 1);
    }
  }
}

}  // namespace opspace::urdf_passes
