/// @file report_html.hpp
/// The report as one offline page (scripts/grade writes out/grade/report.html): per problem and
/// test the status, points, findings and hint; for a simulated test the plot of the student's
/// run against the reference's with the check's bound (inline SVG, no script); for a wrong
/// matrix or vector the table of its entries. Every text is HTML-escaped, the student's first
/// of all (student_text.hpp). Each figure carries its numbers in data- attributes (the series,
/// the bound, the final value), which the tests read instead of the picture.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "report/html_text.hpp"
#include "report/report.hpp"

namespace opspace::grading {

/// Writes the page of `problems`, leaving out the tests of `hidden` as print_report() does;
/// `seed` is the run's (the replay commands name it).
void write_html_report(std::ostream& out, const std::vector<ProblemResult>& problems,
                       const std::vector<std::string>& hidden, std::uint64_t seed);

/// One figure as inline SVG: the reference's series, the student's, the bound and the part of
/// the run the check does not read, shaded.
std::string svg_plot(const RunFigure& figure);

/// One curve of a small multiple: a run's series (SI, as RunFigure::student), its colour and how
/// many students' runs it stands for (identical runs are drawn once).
struct SmallCurve {
  Series series;
  std::string colour;
  int students = 1;
};

/// Many runs of one figure's quantity in a plot of `width` x `height` px, the class page's small
/// multiple: `frame` gives the quantity, unit, bound, unjudged start and the reference's run
/// (drawn over the curves, blue), and its `student` series the values the y axis must hold (every
/// run of every small multiple of the figure, so that they share one scale). Each curve is a
/// path of class "run" with data-students, in whole pixels.
std::string svg_small_multiple(const RunFigure& frame, const std::vector<SmallCurve>& curves, double width,
                               double height);


/// The scales of `figure`'s plot as svg_plot() draws them, for the same figure drawn elsewhere
/// (png_plot(), plot_png.hpp): both label the same ticks. Every number here is finite.
struct PlotScales {
  double t_end = 1.0;        ///< the time at the right edge (s), positive
  double judged_from = 0.0;  ///< where the check starts reading the run (s), within [0, t_end]
  double y_lo = 0.0, y_hi = 1.0;  ///< the value axis's range (shown units)
  bool y_log = false;        ///< a logarithmic value axis (y_lo > 0)
  bool y_clipped = false;    ///< the student's run goes above y_hi
  std::vector<double> t_ticks, y_ticks;  ///< the labelled values, kMaxTicks (12) at most each
  /// Where time t lies across the plot: 0 its left edge, 1 its right, clamped to [-1, 2].
  double x(double t) const;
  /// Where shown value v lies up the plot: 0 its bottom, 1 its top, clamped to [0, 1]
  /// (v finite; the caller leaves out what is not).
  double y(double v) const;
};
PlotScales plot_scales(const RunFigure& figure);

/// A tick's label as the page's axes write it (4 significant digits).
std::string tick_label(double v);

/// "t (s) | yours | reference" rows of `figure` at the times that matter (the run's start, the
/// start of what the check reads, the student's extreme there, the end): for results.json,
/// which shows text only (docs/grader.md).
std::string run_table(const RunFigure& figure);

}  // namespace opspace::grading
