/// @file raster.hpp
/// A small indexed-colour picture and its PNG bytes: how a simulated test's plot travels inside
/// results.json, as <img src="data:image/png;base64,...">, the form Gradescope's HTML output
/// keeps (docs/grader.md, "In an autograder"). Lines, rectangles and the characters of numbers;
/// every other text of a figure stays in the HTML around it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace opspace::grading {

class Raster {
 public:
  /// A `width` x `height` picture of `palette` colours (0xRRGGBB each), filled with colour 0.
  Raster(int width, int height, std::vector<std::uint32_t> palette);

  /// A filled rectangle [x0, x1) x [y0, y1), clipped to the picture.
  void rect(double x0, double y0, double x1, double y1, std::uint8_t colour);
  /// A line `thick` pixels wide; `dash` > 0: drawn `dash` pixels, then left out as many.
  void line(double x0, double y0, double x1, double y1, std::uint8_t colour, int thick = 1, int dash = 0);
  /// Digits, '.', '-', '+' and 'e' in a 5 x 7 font whose left edge is x, or right edge when
  /// `right`, and vertical centre y; any other character is a blank.
  void number(const std::string& text, double x, double y, std::uint8_t colour, bool right = false);

  /// The picture as a PNG file's bytes (8-bit indexed colour, zlib-compressed rows).
  std::string png() const;

 private:
  void dot(int x, int y, std::uint8_t colour);
  int width_, height_;
  std::vector<std::uint32_t> palette_;
  std::vector<std::uint8_t> pixels_;
};

/// `bytes` in base64 (RFC 4648, with padding): for a data: URI.
std::string base64(const std::string& bytes);

}  // namespace opspace::grading
