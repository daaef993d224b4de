#include "report/png_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#if OPSPACE_HAVE_CAIRO
#include <png.h>
#endif

namespace opspace::grading {

#if OPSPACE_HAVE_CAIRO
std::string indexed_png(const std::vector<std::uint32_t>& pixels, int width, int height,
                        const std::vector<std::uint32_t>& exact) {
  if (pixels.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    throw std::invalid_argument("indexed_png: the pixels are not width x height");
  for (const int levels : {16, 11, 8, 6}) {
    const auto rounded = [levels, &exact](std::uint32_t c) {
      if (std::find(exact.begin(), exact.end(), c) != exact.end()) return c;
      std::uint32_t out = 0;
      for (const int shift : {16, 8, 0}) {
        const long step = std::lround(static_cast<double>(c >> shift & 0xff) * (levels - 1) / 255.0);
        out |= static_cast<std::uint32_t>(std::lround(static_cast<double>(step) * 255.0 / (levels - 1))) << shift;
      }
      return out;
    };
    std::unordered_map<std::uint32_t, std::uint8_t> index;
    std::vector<std::uint8_t> colormap, indices;  // RGB triplets; one index a pixel
    indices.reserve(pixels.size());
    bool fits = true;
    for (const std::uint32_t c : pixels) {
      const std::uint32_t q = rounded(c);
      auto found = index.find(q);
      if (found == index.end()) {
        if (index.size() == 256) {
          fits = false;
          break;
        }
        found = index.emplace(q, static_cast<std::uint8_t>(index.size())).first;
        colormap.insert(colormap.end(), {static_cast<std::uint8_t>(q >> 16), static_cast<std::uint8_t>(q >> 8),
                                         static_cast<std::uint8_t>(q)});
      }
      indices.push_back(found->second);
    }
    if (!fits) continue;
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(width), image.height = static_cast<png_uint_32>(height);
    image.format = PNG_FORMAT_RGB_COLORMAP;
    image.colormap_entries = static_cast<png_uint_32>(index.size());
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&image, nullptr, &size, 0, indices.data(), width, colormap.data()))
      break;
    std::string png(size, '\0');
    if (!png_image_write_to_memory(&image, png.data(), &size, 0, indices.data(), width, colormap.data())) break;
    png.resize(size);
    return png;
  }
  throw std::runtime_error("libpng could not write a figure");
}

#endif

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
