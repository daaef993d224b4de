#include "report/report_html.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <sstream>

#include "report/html_text.hpp"
#include "common/student_text.hpp"

namespace opspace::grading {

namespace {

// The plot's box (px): the axes' margins around the data area.
constexpr double kWidth = 640, kHeight = 240, kLeft = 64, kRight = 16, kTop = 14, kBottom = 36;
// A student's series far beyond the scale of the bound and of the reference's run would squash
// both onto the axis: beyond this many times that scale, a quantity that is never negative is
// drawn on a logarithmic axis (from a thousandth of that scale), any other is cut at the top.
constexpr double kClipFactor = 12.0;
// A value beyond this (once scaled) is drawn as if it were this, and a logarithmic axis starts
// at its inverse at the lowest: spans, ratios and steps between any two stay finite, and no
// graded quantity comes near it (issue 59: 1e306 m shown in mm was infinite and hung the ticks).
constexpr double kLargestDrawn = 1e100;
// The labels of an axis, at most: a round step gives at most its count + 1 (9 on the time axis),
// and a logarithmic axis of more decades labels every few; whatever the range, a tick loop ends.
constexpr std::size_t kMaxTicks = 12;

// The pages' text and numbers (html_text.hpp), by their short names here.
constexpr auto text = &html_text;
constexpr auto num = &html_number;
constexpr auto exact = &exact_number;
constexpr auto joined = &joined_numbers;

// A round step for about `count` ticks over `span` (1, 2 or 5 times a power of ten).
double tick_step(double span, int count) {
  const double raw = span / count;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0})
    if (m * magnitude >= raw) return m * magnitude;
  return 10.0 * magnitude;
}

// The multiples of a round step from `lo` to `hi`, about `count` of them and never more than
// kMaxTicks; none when the step is not a positive number (a span too small or not finite).
std::vector<double> linear_ticks(double lo, double hi, int count) {
  std::vector<double> ticks;
  const double step = tick_step(hi - lo, count);
  if (!(step > 0.0) || !std::isfinite(step)) return ticks;
  for (double v = std::ceil(lo / step) * step; v <= hi * (1 + 1e-9) + 1e-300 && ticks.size() < kMaxTicks; v += step)
    ticks.push_back(v);
  return ticks;
}

// v, not NaN, as drawn: within +-kLargestDrawn.
double drawn(double v) { return std::clamp(v, -kLargestDrawn, kLargestDrawn); }

struct Range {
  double lo = 0.0, hi = 1.0;
  bool clipped = false;  // the student's series goes above hi
  bool log = false;      // a logarithmic axis from lo > 0 to hi

  // The height of value v in the data area, 0 (bottom) to 1 (top), v clamped to the range.
  double at(double v) const {
    v = std::clamp(v, lo, hi);
    return log ? std::log10(v / lo) / std::log10(hi / lo) : (v - lo) / (hi - lo);
  }
};

// The y range of `f`'s shown values: 0, both series, the bound; cut at kClipFactor times the
// scale of the bound and the reference's run when the student's goes far beyond it.
Range y_range(const RunFigure& f) {
  double lo = 0.0, hi = 0.0, scale = 0.0;
  // A value not finite (a run that diverged) is a gap; one beyond kLargestDrawn, scaled, is drawn at it.
  const auto see = [&](double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, drawn(v * f.unit_scale));
    hi = std::max(hi, drawn(v * f.unit_scale));
  };
  for (const double v : f.student.v) see(v);
  for (const double v : f.reference.v) {
    see(v);
    if (std::isfinite(v)) scale = std::max(scale, std::abs(drawn(v * f.unit_scale)));
  }
  if (std::isfinite(f.bound)) {
    see(f.bound);
    scale = std::max(scale, std::abs(drawn(f.bound * f.unit_scale)));
  }
  Range r{lo, hi, false, false};
  // A bound far below the top of a quantity that is never negative (1b's ratio test: the
  // reference's ratio in the thousands, the bound 10, a student's near 1) would lie on the axis:
  // a logarithmic axis from a thousandth of the bound keeps the bound and both runs readable.
  const double bound = std::isfinite(f.bound) ? drawn(f.bound * f.unit_scale) : 0.0;
  if (lo >= 0.0 && bound > 0.0 && hi > 100.0 * bound) {
    r.log = true;
    r.lo = std::pow(10.0, std::floor(std::log10(bound / 1000.0)));
    r.hi = std::pow(10.0, std::ceil(std::log10(hi)));
  } else if (scale > 0.0 && hi > kClipFactor * scale) {
    if (lo >= 0.0) {
      r.log = true;
      r.lo = std::pow(10.0, std::floor(std::log10(scale / 1000.0)));
      r.hi = std::pow(10.0, std::ceil(std::log10(hi)));
    } else {
      r.hi = kClipFactor * scale, r.clipped = true;
    }
  }
  // From a bound or scale of a denormal number a thousandth is 0; up from a googol, a power of
  // ten past kLargestDrawn: both axes kept within it.
  if (r.log) r.lo = std::max(r.lo, 1.0 / kLargestDrawn), r.hi = std::min(r.hi, kLargestDrawn);
  if (r.log && r.hi <= r.lo) r.hi = 10.0 * r.lo;
  if (r.hi - r.lo <= 0.0) r.hi = r.lo + 1.0;
  return r;
}

// A plot's box (px): its size and the axes' margins around the data area.
struct Box {
  double width = kWidth, height = kHeight, left = kLeft, right = kRight, top = kTop, bottom = kBottom;
  double w() const { return width - left - right; }
  double h() const { return height - top - bottom; }
};

// The horizontal position of time t in `box` (px): t_end at the right, a time beyond the run (a
// results.json's, to the class page) within a width of the box on either side.
double x_at(double t, double t_end, const Box& box) { return box.left + box.w() * std::clamp(t / t_end, -1.0, 2.0); }

// The points of `s` in the plot's pixels, values clipped to the range; `precision` decimals.
std::string points(const Series& s, double scale, double t_end, const Range& y, const Box& box = {}, int precision = 1) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(precision);
  bool first = true;
  for (std::size_t k = 0; k < s.t.size() && k < s.v.size(); ++k) {
    if (!std::isfinite(s.v[k]) || !std::isfinite(s.t[k])) continue;
    out << (first ? "" : " ") << x_at(s.t[k], t_end, box) << "," << box.top + box.h() * (1.0 - y.at(s.v[k] * scale));
    first = false;
  }
  return out.str();
}

// The points of `s` as an SVG path's data in whole pixels, each point after the first relative
// to the one before ("M40 120l1 -2 1 0"), a point on the pixel before left out, values clipped
// to the range: a third of points()'s text, for the class page's hundreds of runs.
std::string path_data(const Series& s, double scale, double t_end, const Range& y, const Box& box) {
  std::string out;
  long x0 = 0, y0 = 0;
  for (std::size_t k = 0; k < s.t.size() && k < s.v.size(); ++k) {
    if (!std::isfinite(s.v[k]) || !std::isfinite(s.t[k])) continue;
    const long x = std::lround(x_at(s.t[k], t_end, box));
    const long yy = std::lround(box.top + box.h() * (1.0 - y.at(s.v[k] * scale)));
    if (out.empty()) out = "M" + std::to_string(x) + " " + std::to_string(yy) + "l";
    else if (x != x0 || yy != y0) out += std::to_string(x - x0) + " " + std::to_string(yy - y0) + " ";
    x0 = x, y0 = yy;
  }
  if (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// The last time of either run (s): 1 when none is a positive number, at most kLargestDrawn.
double end_time(const RunFigure& f) {
  double t_end = 0.0;
  for (const Series* s : {&f.student, &f.reference})
    if (!s->t.empty() && std::isfinite(s->t.back())) t_end = std::max(t_end, s->t.back());
  return t_end > 0.0 ? std::min(t_end, kLargestDrawn) : 1.0;
}

// Where the check starts reading the run, within it (0 when not a number).
double judged_from(const RunFigure& f, double t_end) {
  return std::isfinite(f.judged_from) ? std::clamp(f.judged_from, 0.0, t_end) : 0.0;
}

// The values labelled on the y axis of `y`: its powers of ten (logarithmic), else about five
// round steps. The page's SVG and results.json's PNG label the same ones.
// Of more decades than kMaxTicks, every few of them, so many that kMaxTicks hold the axis.
std::vector<double> y_ticks(const Range& y) {
  if (!y.log) return linear_ticks(y.lo, y.hi, 5);
  std::vector<double> ticks;
  const double decades = std::round(std::log10(y.hi / y.lo));
  const double every = std::max(1.0, std::ceil(decades / static_cast<double>(kMaxTicks - 1)));
  const double factor = std::pow(10.0, every);
  for (double v = y.lo; v <= y.hi * (1 + 1e-9) && ticks.size() < kMaxTicks; v *= factor) ticks.push_back(v);
  return ticks;
}

void axes(std::ostream& out, double t_end, const Range& y, const std::string& unit, const Box& box = {}, int t_ticks = 8) {
  const double w = box.w(), h = box.h();
  const auto px = [&](double t) { return box.left + w * t / t_end; };
  const auto py = [&](double v) { return box.top + h * (1.0 - y.at(v)); };
  out << "<rect x=\"" << box.left << "\" y=\"" << box.top << "\" width=\"" << w << "\" height=\"" << h
      << "\" fill=\"none\" stroke=\"#888\"/>\n";
  for (const double t : linear_ticks(0.0, t_end, t_ticks))
    out << "<text x=\"" << px(t) << "\" y=\"" << box.height - box.bottom + 16 << "\" text-anchor=\"middle\">" << num(t, 4)
        << "</text>\n";
  out << "<text x=\"" << box.left + w / 2 << "\" y=\"" << box.height - 4 << "\" text-anchor=\"middle\">t (s)</text>\n";
  for (const double v : y_ticks(y))
    out << "<text x=\"" << box.left - 6 << "\" y=\"" << py(v) + 4 << "\" text-anchor=\"end\">" << num(v, 4) << "</text>\n"
        << "<line x1=\"" << box.left << "\" x2=\"" << box.width - box.right << "\" y1=\"" << py(v) << "\" y2=\"" << py(v)
        << "\" stroke=\"#eee\"/>\n";
  out << "<text x=\"14\" y=\"" << box.top + h / 2 << "\" transform=\"rotate(-90 14 " << box.top + h / 2
      << ")\" text-anchor=\"middle\">" << text(unit) << (y.log ? " (log scale)" : "") << "</text>\n";
}

// The opening <svg> of a plot in `box`, the part of the run the check does not read shaded,
// and the axes.
void plot_open(std::ostream& out, const RunFigure& f, const Range& y, double t_end, const Box& box, int t_ticks,
               const std::string& font_size) {
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << box.width << "\" height=\"" << box.height
      << "\" viewBox=\"0 0 " << box.width << " " << box.height << "\" font-family=\"sans-serif\" font-size=\"" << font_size
      << "\" role=\"img\">\n";
  if (judged_from(f, t_end) > 0.0)
    out << "<rect class=\"unjudged\" x=\"" << box.left << "\" y=\"" << box.top << "\" width=\""
        << box.w() * judged_from(f, t_end) / t_end << "\" height=\"" << box.h() << "\" fill=\"#f2f2f2\"/>\n";
  axes(out, t_end, y, f.unit, box, t_ticks);
}

// The check's bound, dashed green, across `box`.
void bound_line(std::ostream& out, const RunFigure& f, const Range& y, const Box& box) {
  if (!std::isfinite(f.bound)) return;
  const double yb = box.top + box.h() * (1.0 - y.at(f.bound * f.unit_scale));
  out << "<line class=\"bound\" x1=\"" << box.left << "\" x2=\"" << box.width - box.right << "\" y1=\"" << yb
      << "\" y2=\"" << yb << "\" stroke=\"#2ca02c\" stroke-width=\"1.5\" stroke-dasharray=\"6 4\"/>\n";
}

}  // namespace

std::string svg_plot(const RunFigure& f) {
  const double t_end = end_time(f);
  const Range y = y_range(f);
  const Box box;
  std::ostringstream out;
  plot_open(out, f, y, t_end, box, 8, "11");
  bound_line(out, f, y, box);
  if (!f.reference.t.empty())
    out << "<polyline class=\"reference\" fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"1.5\" points=\""
        << points(f.reference, f.unit_scale, t_end, y) << "\"/>\n";
  out << "<polyline class=\"student\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"1.5\" points=\""
      << points(f.student, f.unit_scale, t_end, y) << "\"/>\n";
  out << "</svg>";
  return out.str();
}

std::string svg_small_multiple(const RunFigure& frame, const std::vector<SmallCurve>& curves, double width,
                               double height) {
  const double t_end = end_time(frame);
  const Range y = y_range(frame);
  const Box box{width, height, 40, 6, 6, 30};
  std::ostringstream out;
  plot_open(out, frame, y, t_end, box, 4, "9");
  // Whole pixels: a curve of a few hundred points in a plot of a few hundred pixels.
  for (const SmallCurve& c : curves)
    out << "<path class=\"run\" data-students=\"" << c.students << "\" fill=\"none\" stroke=\"" << text(c.colour)
        << "\" stroke-opacity=\"0.6\" d=\"" << path_data(c.series, frame.unit_scale, t_end, y, box) << "\"/>\n";
  if (!frame.reference.t.empty())
    out << "<polyline class=\"reference\" fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"1.5\" points=\""
        << points(frame.reference, frame.unit_scale, t_end, y, box, 0) << "\"/>\n";
  bound_line(out, frame, y, box);
  out << "</svg>";
  return out.str();
}

double PlotScales::x(double t) const { return std::clamp(t / t_end, -1.0, 2.0); }

double PlotScales::y(double v) const {
  return std::clamp(Range{y_lo, y_hi, y_clipped, y_log}.at(v), 0.0, 1.0);
}

PlotScales plot_scales(const RunFigure& f) {
  PlotScales s;
  s.t_end = end_time(f);
  s.judged_from = judged_from(f, s.t_end);
  const Range y = y_range(f);
  s.y_lo = y.lo, s.y_hi = y.hi, s.y_log = y.log, s.y_clipped = y.clipped;
  s.t_ticks = linear_ticks(0.0, s.t_end, 8);  // svg_plot's 8
  s.y_ticks = y_ticks(y);
  return s;
}

std::string tick_label(double v) { return num(v, 4); }

std::string run_table(const RunFigure& f) {
  if (f.student.t.empty()) return "";
  // The student's extreme where the check reads the run (the sign that breaks the bound).
  std::size_t extreme = f.student.t.size() - 1;
  for (std::size_t k = 0; k < f.student.t.size(); ++k) {
    if (f.student.t[k] < f.judged_from) continue;
    const double v = f.student.v[k], e = f.student.v[extreme];
    if (!std::isfinite(v) || (std::isfinite(e) && (f.upper ? v > e : v < e))) extreme = k;
    if (!std::isfinite(v)) break;
  }
  std::vector<double> times = {f.student.t.front(), f.judged_from, f.student.t[extreme], f.student.t.back()};
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  // The value of `s` at its point nearest `t`.
  const auto at = [](const Series& s, double t) {
    if (s.t.empty()) return std::string("-");
    std::size_t best = 0;
    for (std::size_t k = 1; k < s.t.size(); ++k)
      if (std::abs(s.t[k] - t) < std::abs(s.t[best] - t)) best = k;
    return num(s.v[best], 4);
  };
  Series shown_student = f.student, shown_reference = f.reference;
  for (double& v : shown_student.v) v *= f.unit_scale;
  for (double& v : shown_reference.v) v *= f.unit_scale;
  std::ostringstream out;
  out << "your run beside the reference's: " << f.quantity << " (" << (f.unit.empty() ? "-" : f.unit) << ")";
  if (std::isfinite(f.bound))
    out << ", bound " << (f.upper ? "at most " : "at least ") << num(f.bound * f.unit_scale, 4) << " on " << f.judged;
  out << "\n  t (s)      yours        reference\n";
  for (const double t : times) {
    char row[96];
    std::snprintf(row, sizeof row, "  %-9s  %-11s  %s\n", num(t, 4).c_str(), at(shown_student, t).c_str(),
                  at(shown_reference, t).c_str());
    out << row;
  }
  return out.str();
}

}  // namespace opspace::grading
