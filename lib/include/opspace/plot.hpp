/// @file plot.hpp
/// Plots of a run as PNG and SVG, drawn by gnuplot (Debian's gnuplot-nox). A problem fills
/// Figures (panels of curves and reference levels) after its run; render() writes, next to
/// the log, one data file and one gnuplot script per figure and runs gnuplot on it. Without
/// gnuplot nothing is drawn and the result says why: a missing plotter never stops a run.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace opspace::plot {

enum class Line { kSolid, kDashed };

/// One curve y(x).
struct Series {
  std::string title;  ///< legend entry
  std::vector<double> x, y;
  Line line = Line::kSolid;
  std::string color;  ///< "#rrggbb", or empty for gnuplot's sequence
};

/// A horizontal reference line across a panel: a limit, a set point.
struct Level {
  std::string title;
  double y = 0.0;
  std::string color = "#c0392b";
};

/// One set of axes.
struct Panel {
  std::string title;
  std::string ylabel;
  std::vector<Series> series;
  std::vector<Level> levels;
  bool log_y = false;  ///< logarithmic y axis (values <= 0 are not drawn)

  /// Adds a curve; returns it so that its colour can be set.
  Series& add(std::string title, std::vector<double> x, std::vector<double> y, Line line = Line::kSolid);
  /// Adds a horizontal line at y.
  Panel& level(std::string title, double y);
};

/// One picture: a grid of panels sharing the x label, saved as PREFIX-NAME.png/.svg.
struct Figure {
  Figure() = default;
  /// A figure written as PREFIX-NAME.png/.svg, titled `title_`.
  Figure(std::string name_, std::string title_) : name(std::move(name_)), title(std::move(title_)) {}

  std::string name;   ///< file-name part: lower case, digits, '-'
  std::string title;  ///< over the whole picture
  std::string xlabel = "t (s)";
  std::vector<Panel> panels;
  int columns = 1;          ///< panels per row
  int width = 1100;         ///< pixels
  int row_height = 330;     ///< pixels per row of panels

  /// Appends an empty panel titled `title` with y axis label `ylabel`, and returns it.
  Panel& panel(std::string title, std::string ylabel);
};

/// What render() produced.
struct Output {
  std::vector<std::string> images;  ///< every PNG and SVG written, in figure order
  std::vector<std::string> scripts; ///< the gnuplot scripts (re-run them to restyle)
  std::string skipped;              ///< empty, or why (some) pictures were not drawn
};

/// Settings of render().
struct Options {
  bool svg = true;
  /// A series longer than this is reduced to the minimum and maximum of equal buckets, so that
  /// spikes survive while the files stay small.
  std::size_t max_points = 4000;
};

/// The gnuplot executable: $OPSPACE_GNUPLOT if set (empty or missing: none), else `gnuplot`
/// on PATH; "" when there is none.
std::string find_gnuplot();

/// Writes PREFIX-NAME.dat and .gp for every figure and runs gnuplot on each to draw
/// PREFIX-NAME.png (and .svg). Throws std::runtime_error only if the files cannot be
/// written; a missing or failing gnuplot is reported in Output::skipped.
Output render(const std::vector<Figure>& figures, const std::string& prefix, const Options& options = {});

/// Min/max decimation used by render(): at most about `max_points` points, keeping each
/// bucket's extremes in time order.
void decimate(const std::vector<double>& x, const std::vector<double>& y, std::size_t max_points,
              std::vector<double>& x_out, std::vector<double>& y_out);

}  // namespace opspace::plot
