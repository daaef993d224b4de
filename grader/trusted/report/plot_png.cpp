#include "report/plot_png.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "report/png_file.hpp"
#include "report/report_html.hpp"
#include "common/student_text.hpp"

#if OPSPACE_HAVE_CAIRO
#include <cairo.h>
#endif

namespace opspace::grading {

#if OPSPACE_HAVE_CAIRO

// In a namespace of its own: the grader's units are compiled together (a unity build), and
// these names are common.
namespace {
namespace cairo_plot {

using namespace png_layout;

// The picture's colours (0xRRGGBB): the page's SVG's, and its paper, ink, axes, grid and shade.
using Colour = std::uint32_t;
constexpr Colour kPaper = 0xffffff, kInk = 0x222222, kAxis = 0x888888, kGrid = 0xe6e6e6, kShade = 0xededed,
                 kStudent = 0xd62728, kReference = 0x1f77b4, kBound = 0x2ca02c;
constexpr Colour kColours[] = {kPaper, kInk, kAxis, kGrid, kShade, kStudent, kReference, kBound};
// The space between the top of the data area and the value axis's highest value (px): a bound
// or a run at the top of the range is drawn apart from the box's edge.
constexpr double kHeadroom = 6.0;
// The bound's dashes (px): drawn 7, left out 4, as the page's SVG (6 4) at this line's width.
constexpr double kBoundDash[] = {7.0, 4.0};
// A curve's points, at most: a run's series is a few hundred (run_figure.hpp); a results.json's
// may be anything, so beyond this every k-th is kept, before the points of one pixel column are
// merged to their first, lowest, highest and last (at most 4 a column, about 2200 a curve).
constexpr std::size_t kMaxPoints = 20000;
// A text's bytes before it is measured: a title or a unit from a results.json may be megabytes.
constexpr std::size_t kMaxTextBytes = 160;
constexpr double kQuarterTurn = 1.5707963267948966;  // rad

void colour(cairo_t* cr, Colour c) {
  cairo_set_source_rgb(cr, (c >> 16 & 0xff) / 255.0, (c >> 8 & 0xff) / 255.0, (c & 0xff) / 255.0);
}

// `text` as cairo may show it: valid UTF-8 without control characters (a string that is not
// valid UTF-8 would put the context in an error state and blank the rest of the picture), cut
// to kMaxTextBytes first.
std::string shown(const std::string& text) {
  return escape_student_text(text.substr(0, std::min(text.size(), kMaxTextBytes)), false, false);
}

// The first UTF-8 character's length in bytes of s at i (s valid UTF-8, shown()'s).
std::size_t char_length(const std::string& s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  return c < 0x80 ? 1 : c >= 0xf0 ? 4 : c >= 0xe0 ? 3 : 2;
}

double width_of(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  return e.x_advance;
}

// `text` (shown()'s) cut at a character's end so that it and an ellipsis fit in `width` px.
std::string fitted(cairo_t* cr, const std::string& text, double width) {
  if (width_of(cr, text) <= width) return text;
  std::size_t end = 0;
  for (std::size_t i = 0; i < text.size(); i += char_length(text, i)) {
    if (width_of(cr, text.substr(0, i + char_length(text, i)) + "\u2026") > width) break;
    end = i + char_length(text, i);
  }
  return text.substr(0, std::min(end, text.size())) + "\u2026";
}

enum class Align { kLeft, kCentre, kRight };

// `text` with its baseline's left, centre or right at (x, y); returns its width.
double show(cairo_t* cr, const std::string& text, double x, double y, Align align = Align::kLeft) {
  const double w = width_of(cr, text);
  cairo_move_to(cr, align == Align::kLeft ? x : align == Align::kCentre ? x - w / 2 : x - w, y);
  cairo_show_text(cr, text.c_str());
  return w;
}

void font(cairo_t* cr, double size, bool bold = false) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

// One curve of `s` (SI values times `scale`) in the data area, broken where a value or a time
// is not finite (a run that diverged); every coordinate handed to cairo is finite and within the
// scales' clamps.
void curve(cairo_t* cr, const Series& s, double scale, const PlotScales& p) {
  const double w = kRight - kLeft, h = kBottom - kTop - kHeadroom;
  const std::size_t n = std::min(s.t.size(), s.v.size());
  const std::size_t every = std::max<std::size_t>(1, (n + kMaxPoints - 1) / kMaxPoints);
  struct Point {
    double x, y;
  };
  std::vector<Point> column;  // the points of one pixel column, in order
  bool open = false;          // a path is begun
  // The column's first, lowest, highest and last points, in the order they came.
  const auto flush = [&] {
    if (column.empty()) return;
    std::size_t lo = 0, hi = 0;
    for (std::size_t k = 1; k < column.size(); ++k) {
      if (column[k].y > column[lo].y) lo = k;  // pixels grow downwards
      if (column[k].y < column[hi].y) hi = k;
    }
    std::vector<std::size_t> keep{0, lo, hi, column.size() - 1};
    std::sort(keep.begin(), keep.end());
    keep.erase(std::unique(keep.begin(), keep.end()), keep.end());
    for (const std::size_t k : keep) {
      if (open) cairo_line_to(cr, column[k].x, column[k].y);
      else cairo_move_to(cr, column[k].x, column[k].y), open = true;
    }
    column.clear();
  };
  for (std::size_t k = 0; k < n; k += every) {
    const double v = s.v[k] * scale;
    if (!std::isfinite(v) || !std::isfinite(s.t[k])) {
      flush();
      open = false;  // a gap: the next point begins a new piece
      continue;
    }
    const Point q{kLeft + w * p.x(s.t[k]), kBottom - h * p.y(v)};
    if (!column.empty() && std::floor(q.x) != std::floor(column.back().x)) flush();
    column.push_back(q);
  }
  flush();
  cairo_stroke(cr);
}

// A legend entry's sample left of (x, baseline y): a line 2 px thick (dashed or not) or a shaded
// box, 22 px wide, on whole pixels (each of its pixels its colour, none a blend).
void sample(cairo_t* cr, double x, double y, Colour c, bool dashed, bool box) {
  x = std::round(x), y = std::round(y);
  if (box) {
    colour(cr, c);
    cairo_rectangle(cr, x + 0.5, y - 8.5, 21, 10);
    cairo_fill_preserve(cr);
    colour(cr, kAxis);
    cairo_set_line_width(cr, 1);
    cairo_stroke(cr);
    return;
  }
  colour(cr, c);
  cairo_set_line_width(cr, 2);
  if (dashed) cairo_set_dash(cr, kBoundDash, 2, 0);
  cairo_move_to(cr, x, y - 4);
  cairo_line_to(cr, x + 22, y - 4);
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
}

// The picture's pixels (CAIRO_FORMAT_RGB24: xRGB), as png_file.hpp's indexed PNG, the colours
// drawn kept exactly.
std::string indexed_png(cairo_surface_t* surface) {
  cairo_surface_flush(surface);
  const int width = cairo_image_surface_get_width(surface), height = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  std::vector<std::uint32_t> pixels;
  pixels.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < width; ++x) pixels.push_back(row[x] & 0xffffff);
  }
  return grading::indexed_png(pixels, width, height, {std::begin(kColours), std::end(kColours)});
}

void draw(cairo_t* cr, const RunFigure& f) {
  const PlotScales p = plot_scales(f);
  const double w = kRight - kLeft, h = kBottom - kTop;
  const auto px = [&](double t) { return kLeft + w * p.x(t); };
  const auto py = [&](double v) { return kBottom - (h - kHeadroom) * p.y(v); };
  // A unit is a few characters ("mm", "rad/s"): one of a results.json cut at 16, so that the
  // value axis's name, which always shows it, fits.
  std::string unit = shown(f.unit);
  for (std::size_t i = 0, chars = 0; i < unit.size(); i += char_length(unit, i))
    if (++chars > 16) {
      unit = unit.substr(0, i) + "\u2026";
      break;
    }
  const std::string quantity = f.quantity.empty() ? std::string("the run") : shown(f.quantity);

  // Unhinted grey-antialiased glyphs: the same pixels wherever the same cairo and font draw them.
  cairo_font_options_t* options = cairo_font_options_create();
  cairo_font_options_set_antialias(options, CAIRO_ANTIALIAS_GRAY);
  cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
  cairo_set_font_options(cr, options);
  cairo_font_options_destroy(options);

  colour(cr, kPaper);
  cairo_paint(cr);

  // The title: the quantity with its unit, then what the check reads of it.
  colour(cr, kInk);
  font(cr, 13, true);
  const std::string title = fitted(cr, quantity + (unit.empty() ? "" : " (" + unit + ")"), kWidth - 16);
  const double title_width = show(cr, title, 8, kTitleBottom - 5);
  if (!f.judged.empty() && title_width < kWidth - 120) {
    font(cr, 11);
    show(cr, fitted(cr, "  judged: " + shown(f.judged), kWidth - 8 - (8 + title_width)), 8 + title_width, kTitleBottom - 5);
  }

  // The legend: yours, the reference's, the bound, and the unjudged start when there is one.
  struct Entry {
    std::string text;
    Colour c;
    bool dashed, box;
  };
  std::vector<Entry> entries{{p.y_clipped ? "your run (leaves the plot at the top)" : "your run", kStudent, false, false},
                             {f.reference.t.empty() ? "reference run (none)" : "reference run", kReference, false, false}};
  if (std::isfinite(f.bound))
    entries.push_back({std::string("bound: ") + (f.upper ? "at most " : "at least ") +
                           tick_label(std::clamp(f.bound * f.unit_scale, -1e100, 1e100)) + (unit.empty() ? "" : " " + unit),
                       kBound, true, false});
  else
    entries.push_back({"bound: none drawn", kBound, true, false});
  if (p.judged_from > 0.0) entries.push_back({"not judged (before " + tick_label(p.judged_from) + " s)", kShade, false, true});
  // 11 px, or smaller until the entries fit on the line (a long unit), at 8 px cut to fit.
  double size = 11;
  const auto line_width = [&] {
    double total = 0;
    for (const Entry& e : entries) total += 22 + 5 + width_of(cr, e.text) + 16;
    return total;
  };
  for (font(cr, size); size > 8 && line_width() > kWidth - 16; font(cr, --size)) {
  }
  double x = 8;
  const double baseline = kLegendBottom - 7;
  for (const Entry& e : entries) {
    sample(cr, x, baseline, e.c, e.dashed, e.box);
    colour(cr, kInk);
    x += 27 + show(cr, fitted(cr, e.text, std::max(0.0, kWidth - 8 - (x + 27))), x + 27, baseline) + 16;
  }

  // The data area: the unjudged start shaded, the grid at the value ticks.
  if (p.judged_from > 0.0) {
    colour(cr, kShade);
    cairo_rectangle(cr, kLeft, kTop, px(p.judged_from) - kLeft, h);
    cairo_fill(cr);
  }
  cairo_set_line_width(cr, 1);
  font(cr, 10);
  for (const double v : p.y_ticks) {
    const double y = std::round(py(v)) + 0.5;  // a crisp 1 px line
    colour(cr, kGrid);
    cairo_move_to(cr, kLeft, y);
    cairo_line_to(cr, kRight, y);
    cairo_stroke(cr);
    colour(cr, kInk);
    show(cr, fitted(cr, tick_label(v), kLeft - 28), kLeft - 5, y + 3.5, Align::kRight);
  }
  for (const double t : p.t_ticks) {
    const double x_tick = std::round(px(t)) + 0.5;
    colour(cr, kAxis);
    cairo_move_to(cr, x_tick, kBottom);
    cairo_line_to(cr, x_tick, kBottom + 4);
    cairo_stroke(cr);
    colour(cr, kInk);
    show(cr, tick_label(t), x_tick, kBottom + 15, Align::kCentre);
  }
  colour(cr, kAxis);
  cairo_rectangle(cr, kLeft + 0.5, kTop + 0.5, w - 1, h - 1);
  cairo_stroke(cr);

  // The axes' names: time below, the quantity up the left side.
  colour(cr, kInk);
  font(cr, 11);
  show(cr, "time t (s)", kLeft + w / 2, kHeight - 10, Align::kCentre);
  // Along the data area's height and 20 px more: the quantity cut to fit, never its unit.
  const std::string y_unit = (unit.empty() ? "" : " (" + unit + ")") + (p.y_log ? ", log scale" : "");
  const std::string y_name = fitted(cr, quantity, std::max(0.0, h + 20 - width_of(cr, y_unit))) + y_unit;
  cairo_save(cr);
  cairo_translate(cr, 16, kTop + h / 2);
  cairo_rotate(cr, -kQuarterTurn);  // reads upwards
  show(cr, y_name, 0, 0, Align::kCentre);
  cairo_restore(cr);

  // The bound, the reference's run, then yours on top, inside the data area only.
  cairo_save(cr);
  cairo_rectangle(cr, kLeft, kTop, w, h);
  cairo_clip(cr);
  if (std::isfinite(f.bound)) {
    colour(cr, kBound);
    cairo_set_line_width(cr, 2);
    cairo_set_dash(cr, kBoundDash, 2, 0);
    const double y = py(f.bound * f.unit_scale);
    cairo_move_to(cr, kLeft, y);
    cairo_line_to(cr, kRight, y);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
  }
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_width(cr, 1.75);
  colour(cr, kReference);
  curve(cr, f.reference, f.unit_scale, p);
  colour(cr, kStudent);
  curve(cr, f.student, f.unit_scale, p);
  cairo_restore(cr);
}

}  // namespace cairo_plot
}  // namespace

std::string png_plot(const RunFigure& f) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, png_layout::kWidth, png_layout::kHeight);
  cairo_t* cr = cairo_create(surface);
  cairo_plot::draw(cr, f);
  const cairo_status_t status = cairo_status(cr);
  cairo_destroy(cr);
  std::string png;
  try {
    if (status == CAIRO_STATUS_SUCCESS) png = cairo_plot::indexed_png(surface);
  } catch (...) {
    cairo_surface_destroy(surface);
    throw;
  }
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("cairo could not draw a figure: ") + cairo_status_to_string(status));
  return png;
}

#if defined(__SANITIZE_ADDRESS__)  // GCC's -fsanitize=address
#define OPSPACE_PLOT_PNG_LSAN 1
#elif defined(__has_feature)  // clang's
#if __has_feature(address_sanitizer)
#define OPSPACE_PLOT_PNG_LSAN 1
#endif
#endif
#ifdef OPSPACE_PLOT_PNG_LSAN
// LeakSanitizer's suppressions in a sanitized build (the asan preset) of every program that draws
// a picture: Debian 12's fontconfig 2.14 keeps 652 bytes unreachable when cairo first resolves
// "DejaVu Sans" (normal and bold), once per process whatever the number of pictures (measured: 2
// and 100 pictures leak the same). Not ours to free; everything else is still reported.
// The suppression is not listed at exit (print_suppressions=0): a program's output stays its own.
extern "C" const char* __lsan_default_suppressions() { return "leak:libfontconfig.so\n"; }
extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }
#endif

#else  // a grader built without cairo (a student handout's): no picture

std::string png_plot(const RunFigure&) { return ""; }

#endif

}  // namespace opspace::grading
