/// @file png_file.hpp
/// A picture's bytes for results.json: an 8-bit indexed PNG written by libpng, and base64 for the
/// data: URI that carries it (Gradescope's <img src="data:image/png;base64,...">, PrairieLearn's
/// images[]). plot_png.hpp draws the picture.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace opspace::grading {

/// `pixels` (0xRRGGBB, `width` x `height`, row by row) as an 8-bit indexed PNG: a third of the
/// bytes of a 24-bit PNG (20-39 KB for a real run's figure), so that a grading's every picture
/// fits in results.json's 1 MB. The colours in `exact` are kept exactly; the others (the blends
/// of antialiased edges) are rounded to 16 levels a channel, then 11, 8 and 6 while they are more
/// than 256 (6 levels make 216 colours, which always fit with a few exact ones). Throws
/// std::invalid_argument if `pixels` is not width x height, std::runtime_error if libpng fails;
/// where the grader was built without libpng (a student handout's), it is not defined.
std::string indexed_png(const std::vector<std::uint32_t>& pixels, int width, int height,
                        const std::vector<std::uint32_t>& exact);

/// `bytes` in base64 (RFC 4648, with padding): for a data: URI.
std::string base64(const std::string& bytes);

}  // namespace opspace::grading
