/// @file plot_png.hpp
/// A simulated test's plot as a PNG file's bytes, drawn by cairo (Debian's libcairo2): the
/// picture results.json carries, in Gradescope's HTML as <img src="data:image/png;base64,...">
/// and in PrairieLearn's images[] (docs/grader.md, "In an autograder"). PrairieLearn shows a
/// picture apart from the text, so the picture says what it is by itself: a title (the quantity,
/// its unit, what the check reads), a legend (your run red, the reference's blue, the bound
/// dashed green, the unjudged start shaded), the axes' names with their units, and the tick
/// numbers of the page's SVG plot (report_html.hpp, plot_scales()). Text is cairo's own ("toy")
/// text in DejaVu Sans (fonts-dejavu-core), found by fontconfig, unhinted, so that the same
/// libraries and font draw the same pixels.
///
/// Whatever the figure holds (a results.json's numbers, read back by the class page, are
/// hostile), cairo gets finite coordinates within a few widths of the picture, at most a few
/// thousand points a curve, and texts of valid UTF-8 cut to fit: the drawing ends promptly.
#pragma once

#include <string>

#include "judge/figure.hpp"
#include "report/png_file.hpp"  // base64(), for the callers that carry the picture

namespace opspace::grading {

/// The picture's size and where its parts are (px): the tests read these regions.
namespace png_layout {
constexpr int kWidth = 640, kHeight = 300;
/// The title's line and the legend's line, above the plot.
constexpr int kTitleTop = 2, kTitleBottom = 22, kLegendTop = 24, kLegendBottom = 44;
/// The data area: the axes' box.
constexpr int kLeft = 80, kRight = 624, kTop = 52, kBottom = 252;
}  // namespace png_layout

/// `figure` as a PNG file's bytes, png_layout::kWidth x kHeight, 24-bit RGB. Empty where the
/// grader was built without cairo (a student handout's, which has no simulated test:
/// grader/CMakeLists.txt); the callers then leave the picture out.
std::string png_plot(const RunFigure& figure);

}  // namespace opspace::grading
