#include "report/raster.hpp"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace opspace::grading {

namespace {

// 5 x 7 glyphs, one row a byte, the top row first, bit 4 the leftmost pixel.
struct Glyph {
  char c;
  std::uint8_t rows[7];
};
constexpr Glyph kGlyphs[] = {
    {'0', {0x0e, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0e}}, {'1', {0x04, 0x0c, 0x04, 0x04, 0x04, 0x04, 0x0e}},
    {'2', {0x0e, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1f}}, {'3', {0x1f, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0e}},
    {'4', {0x02, 0x06, 0x0a, 0x12, 0x1f, 0x02, 0x02}}, {'5', {0x1f, 0x10, 0x1e, 0x01, 0x01, 0x11, 0x0e}},
    {'6', {0x06, 0x08, 0x10, 0x1e, 0x11, 0x11, 0x0e}}, {'7', {0x1f, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0e, 0x11, 0x11, 0x0e, 0x11, 0x11, 0x0e}}, {'9', {0x0e, 0x11, 0x11, 0x0f, 0x01, 0x02, 0x0c}},
    {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0c, 0x0c}}, {'-', {0x00, 0x00, 0x00, 0x1f, 0x00, 0x00, 0x00}},
    {'+', {0x00, 0x04, 0x04, 0x1f, 0x04, 0x04, 0x00}}, {'e', {0x00, 0x00, 0x0e, 0x11, 0x1f, 0x10, 0x0e}},
};
constexpr int kAdvance = 6;  // 5 columns and one of space

const Glyph* glyph(char c) {
  for (const Glyph& g : kGlyphs)
    if (g.c == c) return &g;
  return nullptr;
}

void put32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((v >> shift) & 0xff);
}

// A PNG chunk: length, type, data, CRC-32 of type and data.
void chunk(std::string& out, const char* type, const std::string& data) {
  put32(out, static_cast<std::uint32_t>(data.size()));
  const std::string body = std::string(type, 4) + data;
  out += body;
  put32(out, static_cast<std::uint32_t>(
                 crc32(0L, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()))));
}

}  // namespace

Raster::Raster(int width, int height, std::vector<std::uint32_t> palette)
    : width_(width), height_(height), palette_(std::move(palette)),
      pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0) {
  if (width <= 0 || height <= 0 || palette_.empty() || palette_.size() > 256)
    throw std::invalid_argument("a raster needs a positive size and 1 to 256 colours");
}

void Raster::dot(int x, int y, std::uint8_t colour) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  pixels_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)] = colour;
}

void Raster::rect(double x0, double y0, double x1, double y1, std::uint8_t colour) {
  const int xa = std::max(0, static_cast<int>(std::lround(std::min(x0, x1))));
  const int xb = std::min(width_, static_cast<int>(std::lround(std::max(x0, x1))));
  const int ya = std::max(0, static_cast<int>(std::lround(std::min(y0, y1))));
  const int yb = std::min(height_, static_cast<int>(std::lround(std::max(y0, y1))));
  for (int y = ya; y < yb; ++y)
    for (int x = xa; x < xb; ++x) dot(x, y, colour);
}

void Raster::line(double x0, double y0, double x1, double y1, std::uint8_t colour, int thick, int dash) {
  if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1)) return;
  const double length = std::hypot(x1 - x0, y1 - y0);
  const int steps = std::max(1, static_cast<int>(std::ceil(length * 2)));  // half-pixel steps
  for (int k = 0; k <= steps; ++k) {
    if (dash > 0 && static_cast<int>(length * k / steps) / dash % 2 == 1) continue;
    const double x = x0 + (x1 - x0) * k / steps, y = y0 + (y1 - y0) * k / steps;
    const int cx = static_cast<int>(std::lround(x)), cy = static_cast<int>(std::lround(y));
    for (int dy = -(thick - 1) / 2; dy <= thick / 2; ++dy)
      for (int dx = -(thick - 1) / 2; dx <= thick / 2; ++dx) dot(cx + dx, cy + dy, colour);
  }
}

void Raster::number(const std::string& text, double x, double y, std::uint8_t colour, bool right) {
  int left = static_cast<int>(std::lround(right ? x - kAdvance * static_cast<double>(text.size()) : x));
  const int top = static_cast<int>(std::lround(y)) - 3;
  for (const char c : text) {
    if (const Glyph* g = glyph(c)) {
      for (int row = 0; row < 7; ++row)
        for (int column = 0; column < 5; ++column)
          if (g->rows[row] & (0x10 >> column)) dot(left + column, top + row, colour);
    }
    left += kAdvance;
  }
}

std::string Raster::png() const {
  std::string rows;  // each row: filter type 0 (none), then its palette indices
  rows.reserve(pixels_.size() + static_cast<std::size_t>(height_));
  for (int y = 0; y < height_; ++y) {
    rows += '\0';
    const auto begin = pixels_.begin() + static_cast<std::ptrdiff_t>(y) * width_;
    rows.append(begin, begin + width_);
  }
  uLongf size = compressBound(static_cast<uLong>(rows.size()));
  std::string compressed(size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(compressed.data()), &size, reinterpret_cast<const Bytef*>(rows.data()),
                static_cast<uLong>(rows.size()), 9) != Z_OK)
    throw std::runtime_error("zlib could not compress a figure");
  compressed.resize(size);
  std::string header;  // IHDR: width, height, bit depth 8, colour type 3 (indexed), defaults
  put32(header, static_cast<std::uint32_t>(width_));
  put32(header, static_cast<std::uint32_t>(height_));
  header += std::string("\x08\x03\x00\x00\x00", 5);
  std::string palette;
  for (const std::uint32_t c : palette_) palette += {static_cast<char>(c >> 16), static_cast<char>(c >> 8), static_cast<char>(c)};
  std::string out = "\x89PNG\r\n\x1a\n";
  chunk(out, "IHDR", header);
  chunk(out, "PLTE", palette);
  chunk(out, "IDAT", compressed);
  chunk(out, "IEND", "");
  return out;
}

std::string base64(const std::string& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t v = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 2]);
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
  }
  return out;
}

}  // namespace opspace::grading
