/// @file figure.hpp
/// A simulated test's figure: the series of a run it plots, the student's beside the
/// reference's, the bound its check applied, and how the plotted series gives the statistic the
/// test judges. The judge fills it (grading.hpp), the reference's runs are kept for it
/// (reference_store.hpp), the report draws it.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace opspace::grading {

/// A time series of a run, decimated for a plot (run_figure.hpp): times (s) and values (SI).
struct Series {
  std::vector<double> t;
  std::vector<double> v;
};

/// How a figure's plotted series gives the statistic its test judges (RunFigure::plotted), so
/// that the picture and the verdict are one number: plotted_statistic() reads it back.
enum class Plotted {
  kSeries,       ///< the series itself; the test judges something else of the run
  kLargest,      ///< the series; the test judges its largest value from judged_from on
  kRunningRms,   ///< from judged_from on, the RMS of the series since judged_from; judged: its last point
  kRunningMean,  ///< from judged_from on, the mean of the series since judged_from; judged: its last point
  kFinal,        ///< the series; the test judges its last point
};

/// What a simulated test judged, for the report's plot: the student's run and the reference's
/// (the grader's oracle law at the same inputs), and the bound the check applied.
struct RunFigure {
  std::string quantity;     ///< what is plotted, e.g. "tip error |x - x_d|"
  std::string unit;         ///< its unit as shown, e.g. "mm"
  double unit_scale = 1.0;  ///< SI value times this: the value shown
  /// The check's bound on the plotted quantity (SI); NaN: no line drawn.
  double bound = std::numeric_limits<double>::quiet_NaN();
  bool upper = true;        ///< the bound is a maximum (at_most), else a minimum (at_least)
  std::string judged;       ///< what the check reads of the series, e.g. "its largest value after 2 s"
  double judged_from = 0.0;  ///< the check reads the series from this time on (s)
  Plotted plotted = Plotted::kSeries;  ///< how the plotted series gives the judged statistic
  /// The Judgement::statistic the figure draws (empty: none); Check::judge fills in the two
  /// values the verdict used, which plotted_statistic() of the series must give back.
  std::string draws;
  double verdict_yours = std::numeric_limits<double>::quiet_NaN();
  double verdict_reference = std::numeric_limits<double>::quiet_NaN();
  Series student;           ///< the run of the code graded
  Series reference;         ///< the run of the problem set's law, same scenario (reference_store.hpp)
  std::string reference_key;              ///< names the reference's series among all runs'
  std::function<Series()> make_reference;  ///< runs the law for it, when it is not known yet
};

/// The statistic a test judges, read off a figure's plotted series `s` (its student's or its
/// reference's) as `f.plotted` says; NaN for Plotted::kSeries or an empty series.
double plotted_statistic(const RunFigure& f, const Series& s);

}  // namespace opspace::grading
