// results.json's picture of a simulated test (grader/trusted/report/plot_png.hpp), read back with
// cairo's own PNG reader: a PNG of the stated size that says what it is by itself (PrairieLearn
// shows it apart from the text): title, legend of three entries, the axes' names and numbers,
// the three lines in the data area; and a figure of hostile numbers and texts drawn promptly.
// OPSPACE_PLOT_PNG_OUT=DIR writes the pictures drawn here into DIR, to be looked at.
// Seen to fail: with the legend's entries not drawn (its colours' and ink's counts 0); with the
// texts handed to cairo uncleaned (the hostile figure: "input string not valid UTF-8", thrown);
// with every point of a curve drawn (no kMaxPoints, no merging of a pixel column's points: the
// hostile figure still drawing after 300 s); with cairo's own 24-bit PNG (21 KB, over the size).
#include <doctest/doctest.h>

#include <cairo.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

#include "report/plot_png.hpp"
#include "report/report_html.hpp"

namespace grading = opspace::grading;
namespace layout = opspace::grading::png_layout;

namespace {

// A failed test of problem 1b's kind: the tip error in mm, a bound of 2 mm on its largest value
// after 1 s; the student's run settles at 3 mm, above it, the reference's near 0.
grading::RunFigure figure() {
  grading::RunFigure f;
  f.quantity = "tip error |x - x_d|", f.unit = "mm", f.unit_scale = 1000.0;
  f.bound = 0.002, f.upper = true, f.judged = "its largest value after 1 s", f.judged_from = 1.0;
  for (int k = 0; k <= 300; ++k) {  // 3 s sampled every 10 ms, as a decimated run
    const double t = 0.01 * k;
    f.student.t.push_back(t), f.student.v.push_back(0.01 * std::exp(-2.0 * t) + 0.003);
    f.reference.t.push_back(t), f.reference.v.push_back(0.01 * std::exp(-4.0 * t));
  }
  return f;
}

void keep(const std::string& png, const std::string& name) {
  if (const char* dir = std::getenv("OPSPACE_PLOT_PNG_OUT")) std::ofstream(std::string(dir) + "/" + name, std::ios::binary) << png;
}

// The PNG decoded by cairo; its pixels as 0xRRGGBB.
struct Picture {
  int width = 0, height = 0;
  std::vector<std::uint32_t> pixels;
  std::uint32_t at(int x, int y) const { return pixels[static_cast<std::size_t>(y * width + x)]; }
};

Picture decode(const std::string& png) {
  struct Reader {
    const std::string* bytes;
    std::size_t at = 0;
  } reader{&png};
  const auto read = [](void* closure, unsigned char* data, unsigned int length) {
    auto* r = static_cast<Reader*>(closure);
    if (r->bytes->size() - r->at < length) return CAIRO_STATUS_READ_ERROR;
    std::copy_n(r->bytes->data() + r->at, length, data);
    r->at += length;
    return CAIRO_STATUS_SUCCESS;
  };
  cairo_surface_t* s = cairo_image_surface_create_from_png_stream(read, &reader);
  Picture p;
  if (cairo_surface_status(s) == CAIRO_STATUS_SUCCESS) {
    cairo_surface_flush(s);
    p.width = cairo_image_surface_get_width(s), p.height = cairo_image_surface_get_height(s);
    const int stride = cairo_image_surface_get_stride(s);
    const unsigned char* data = cairo_image_surface_get_data(s);
    for (int y = 0; y < p.height; ++y)
      for (int x = 0; x < p.width; ++x)  // native-endian 32-bit pixels, the top byte unused
        p.pixels.push_back(*reinterpret_cast<const std::uint32_t*>(data + y * stride + 4 * x) & 0xffffff);
  }
  cairo_surface_destroy(s);
  return p;
}

// Pixels of [x0, x1) x [y0, y1) within `tolerance` of `colour` in each channel.
int count(const Picture& p, int x0, int y0, int x1, int y1, std::uint32_t colour, int tolerance) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::uint32_t c = p.at(x, y);
      bool near = true;
      for (const int shift : {16, 8, 0})
        near = near && std::abs(static_cast<int>((c >> shift) & 0xff) - static_cast<int>((colour >> shift) & 0xff)) <= tolerance;
      n += near ? 1 : 0;
    }
  return n;
}

// The three lines' colours (plot_png.cpp) and the text's ink, within 40 of 255 a channel: the
// line's own pixels, not the blend of its antialiased edge with the paper (halfway, ~100 off).
constexpr std::uint32_t kRed = 0xd62728, kBlue = 0x1f77b4, kGreen = 0x2ca02c, kInk = 0x222222;
constexpr int kNear = 40;
// Dark pixels: a glyph's stroke (ink 0x22, antialiased, counted darker than mid-grey), which no
// line, grid (0xe6) or shade (0xed) of the picture is.
int ink(const Picture& p, int x0, int y0, int x1, int y1) { return count(p, x0, y0, x1, y1, kInk, 0x60); }

}  // namespace

TEST_CASE("a figure's PNG is a PNG of the layout's size with its title, legend, axes' names and numbers, and its three lines") {
  const std::string png = grading::png_plot(figure());
  keep(png, "plot.png");
  REQUIRE(png.size() > 8);
  CHECK(png.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);  // the PNG signature
  // Small enough for results.json: a grading whose every simulated test fails carries about 20
  // pictures, which must leave most of Gradescope's and PrairieLearn's 1 MB to the texts: at
  // 15 KB, 20 KB as base64, 400 KB. This one is 7.5 KB (a real run's 7-13 KB); cairo's own
  // 24-bit PNG of it is 21 KB.
  CHECK(png.size() < 15 * 1024);
  const Picture p = decode(png);
  REQUIRE(p.width == layout::kWidth);
  REQUIRE(p.height == layout::kHeight);
  // The legend's three samples, each a line 2 px thick and 22 px long on whole pixels: 44
  // pixels in the line's own colour.
  const int legend[] = {0, layout::kLegendTop, layout::kWidth, layout::kLegendBottom};
  CHECK(count(p, legend[0], legend[1], legend[2], legend[3], kRed, kNear) >= 44);
  CHECK(count(p, legend[0], legend[1], legend[2], legend[3], kBlue, kNear) >= 44);
  // The bound's, dashed (7 on, 4 off): 14 of its 22 px, in 2 rows.
  CHECK(count(p, legend[0], legend[1], legend[2], legend[3], kGreen, kNear) >= 28);
  // The legend's words ("your run", "reference run", "bound: at most 2 mm", "not judged (...)"):
  // about 60 characters, at least 10 dark pixels each at 11 px.
  CHECK(ink(p, legend[0], legend[1], legend[2], legend[3]) >= 600);
  // The title (the quantity, its unit, what is judged), bold: at least as much.
  CHECK(ink(p, 0, layout::kTitleTop, layout::kWidth, layout::kTitleBottom) >= 600);
  // The value axis's name, up the left side (left of its tick numbers), about 20 characters.
  CHECK(ink(p, 0, layout::kTop, 24, layout::kBottom) >= 150);
  // Its tick numbers, as the page's SVG labels them (0, 5 and 10 mm here): at least 8 dark
  // pixels each, the fewest a label can have being a single digit's (these three have 53).
  const std::size_t y_labels = grading::plot_scales(figure()).y_ticks.size();
  CHECK(y_labels == 3);
  CHECK(ink(p, 24, layout::kTop - 6, layout::kLeft, layout::kBottom + 6) >= 8 * static_cast<int>(y_labels));
  // The time axis: its numbers (0, 0.5 ... 3: 7 labels, 8 dark pixels each at least, as above)
  // and its name "time t (s)" below the plot (9 characters, at least 50 dark pixels).
  CHECK(grading::plot_scales(figure()).t_ticks.size() == 7);
  CHECK(ink(p, layout::kLeft - 10, layout::kBottom + 5, layout::kRight + 10, layout::kBottom + 20) >= 7 * 8);
  CHECK(ink(p, layout::kLeft, layout::kBottom + 20, layout::kRight, layout::kHeight) >= 50);
  // In the data area: yours and the reference's, each across the 544 px width (at least half of
  // that many pixels of its colour, where they cross), and the dashed bound (7 of every 11).
  const int area[] = {layout::kLeft + 1, layout::kTop + 1, layout::kRight - 1, layout::kBottom - 1};
  CHECK(count(p, area[0], area[1], area[2], area[3], kRed, kNear) >= 272);
  CHECK(count(p, area[0], area[1], area[2], area[3], kBlue, kNear) >= 272);
  CHECK(count(p, area[0], area[1], area[2], area[3], kGreen, kNear) >= 272);
  // Nothing drawn outside the picture's parts: the right margin beyond the legend is paper.
  CHECK(count(p, layout::kRight + 2, layout::kTop, layout::kWidth, layout::kBottom, 0xffffff, 0) ==
        (layout::kWidth - layout::kRight - 2) * (layout::kBottom - layout::kTop));
}

TEST_CASE("a figure of hostile numbers and texts is drawn promptly, its legend and axes still there") {
  // A results.json's figure, as the class page reads it back: values NaN, infinite and 1e306 m
  // shown in mm (infinite once scaled), times to infinity and back, a bound of the smallest
  // double, a judged start at infinity, a million points, and a quantity and unit that are not
  // UTF-8, with control bytes, megabytes long.
  grading::RunFigure f;
  f.quantity = std::string("q\xff\xfe\x1b[31m") + std::string(1 << 20, 'x');
  f.unit = std::string(1 << 20, '\xc3');
  f.unit_scale = 1000, f.bound = 5e-324, f.judged_from = HUGE_VAL, f.judged = "\x80";
  for (int k = 0; k < 1000000; ++k) {  // a zigzag from -1e306 to 1e306 mm, with gaps
    const double t = k % 7 == 0 ? -1e300 : k % 5 == 0 ? HUGE_VAL : k;
    f.student.t.push_back(t);
    f.student.v.push_back(k % 11 == 0 ? NAN : k % 13 == 0 ? 1e306 : k % 2 == 0 ? 1e303 : -1e303);
  }
  f.reference = {{0, 1, 2, NAN}, {0.001, -HUGE_VAL, 1e-320, 1}};
  const auto start = std::chrono::steady_clock::now();
  const std::string png = grading::png_plot(f);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  keep(png, "hostile.png");
  // Measured: 0.04-0.07 s for the figure above (fontconfig's start included), 0.1 s for this one
  // (one in 50 of its million points looked at: plot_png.cpp's kMaxPoints). 3 s: tens of times
  // that, for a loaded machine. A drawing that does not end is stopped by ctest's 60 s.
  CHECK(seconds < 3.0);
  const Picture p = decode(png);
  REQUIRE(p.width == layout::kWidth);
  REQUIRE(p.height == layout::kHeight);
  // The texts were shown (not a blank picture: invalid UTF-8 stops a cairo context's drawing).
  CHECK(ink(p, 0, layout::kTitleTop, layout::kWidth, layout::kTitleBottom) >= 600);
  // The legend's three entries (no unjudged start: it is at infinity), their words 30
  // characters at least, and the bound's sample.
  CHECK(ink(p, 0, layout::kLegendTop, layout::kWidth, layout::kLegendBottom) >= 300);
  CHECK(count(p, 0, layout::kLegendTop, layout::kWidth, layout::kLegendBottom, kGreen, kNear) >= 28);
  CHECK(ink(p, layout::kLeft, layout::kBottom + 20, layout::kRight, layout::kHeight) >= 50);
}

TEST_CASE("base64 pads to a multiple of four digits (RFC 4648's test vectors)") {
  CHECK(grading::base64("") == "");
  CHECK(grading::base64("f") == "Zg==");
  CHECK(grading::base64("fo") == "Zm8=");
  CHECK(grading::base64("foo") == "Zm9v");
  CHECK(grading::base64("foobar") == "Zm9vYmFy");
}
