/// @file visuals/plot.hpp
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
  std::vector<double> x;     ///< abscissae, in the figure's xlabel unit
  std::vector<double> y;     ///< ordinates, one per x, in the panel's ylabel unit
  Line line = Line::kSolid;  ///< solid or dashed (e.g. a desired value)
  std::string color;  ///< "#rrggbb", or empty for gnuplot's sequence
};

/// A horizontal reference line across a panel: a limit, a set point.
struct Level {
  std::string title;              ///< legend entry
  double y = 0.0;                 ///< where it is drawn, in the panel's ylabel unit
  std::string color = "#c0392b";  ///< "#rrggbb"; drawn dotted
};

/// One set of axes.
struct Panel {
  std::string title;           ///< over the panel
  std::string ylabel;          ///< y axis label, with its unit
  std::vector<Series> series;  ///< curves, in legend order
  std::vector<Level> levels;   ///< horizontal lines, after the curves
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
  std::string xlabel = "t (s)";  ///< x axis label of every panel
  std::vector<Panel> panels;     ///< row by row, `columns` per row
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
  bool svg = true;  ///< also write an SVG next to each PNG
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
