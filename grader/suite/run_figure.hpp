/// @file run_figure.hpp
/// A simulated test's figure (grading.hpp: RunFigure): the series its checks read, from the
/// student's run and from the reference's, the run of the problem set's law (the oracle of the
/// test's law pin) in the same scenario. The plotted series is the judged quantity
/// (RunFigure::plotted: a running RMS or mean from the judged window's start on), decimated to
/// what a plot needs so that the statistic read off the plot is the verdict's
/// (plotted_statistic()).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <utility>

#include "judge/grading.hpp"

namespace opspace::grading {

/// At most this many points per series: a plot 640 px wide needs no more, and the thirty
/// series of a full grading stay well under 100 KB of page.
inline constexpr std::size_t kFigurePoints = 240;

/// value(s) of every sample s of `samples`, from `from` on transformed as `how` says (the
/// running RMS or mean since `from`; the series itself otherwise).
template <class Samples, class Value>
Series plotted_series(const Samples& samples, Value value, Plotted how, double from) {
  Series out;
  double sum = 0.0;
  long n = 0;
  for (const auto& s : samples) {
    double v = value(s);
    if (s.t >= from && (how == Plotted::kRunningRms || how == Plotted::kRunningMean)) {
      sum += how == Plotted::kRunningRms ? v * v : v;
      ++n;
      v = how == Plotted::kRunningRms ? std::sqrt(sum / n) : sum / n;
    }
    out.t.push_back(s.t);
    out.v.push_back(v);
  }
  return out;
}

/// `full` decimated to at most kFigurePoints: the first and last sample, the first sample from
/// `from` on (the judged window's edge), and between them, of each stretch of consecutive
/// samples that does not cross `from`, the one of largest value (`largest`: the judged
/// statistic is the largest value) or of largest |value| (a peak stays in the plot); a value
/// that is not finite counts as the largest.
inline Series decimate(const Series& full, double from = 0.0, bool largest = false) {
  Series out;
  const std::size_t n = full.t.size();
  if (n == 0) return out;
  const std::size_t edge = static_cast<std::size_t>(std::lower_bound(full.t.begin(), full.t.end(), from) - full.t.begin());
  const std::size_t per = (n + kFigurePoints - 7) / (kFigurePoints - 6);  // leaves room for the kept samples
  const auto larger = [largest](double a, double b) {
    return !std::isfinite(a) || (std::isfinite(b) && (largest ? a > b : std::abs(a) > std::abs(b)));
  };
  const auto keep = [&](std::size_t k) { out.t.push_back(full.t[k]), out.v.push_back(full.v[k]); };
  // Of each bucket of `per` samples in [begin, end), the extreme one.
  const auto buckets = [&](std::size_t begin, std::size_t end) {
    for (std::size_t first = begin; first < end; first += per) {
      std::size_t best = first;
      for (std::size_t k = first + 1; k < std::min(first + per, end); ++k)
        if (larger(full.v[k], full.v[best])) best = k;
      keep(best);
    }
  };
  keep(0);
  if (n == 1) return out;
  const std::size_t judged = std::clamp<std::size_t>(edge, 1, n - 1);  // the window's first sample
  buckets(1, judged);
  if (edge > 0 && judged < n - 1) {  // a window that starts after the first sample: its edge kept
    keep(judged);
    buckets(judged + 1, n - 1);
  } else {
    buckets(judged, n - 1);
  }
  keep(n - 1);
  return out;
}

/// value(s) of every sample of `samples`, as a figure `f` plots it, decimated.
template <class Samples, class Value>
Series decimate(const Samples& samples, Value value, const RunFigure& f = {}) {
  return decimate(plotted_series(samples, value, f.plotted, f.judged_from), f.judged_from, f.plotted == Plotted::kLargest);
}

/// The figure of `quantity` in the student's run `mine` (its samples), whose reference series
/// is `reference_key` of the reference's run, made from the reference's samples (given by
/// `reference`) only when the report needs it (reference_store.hpp: a passed test's figure
/// shows it when it is known already).
template <class Samples, class Value, class Reference>
RunFigure run_figure(RunFigure figure, const Samples& mine, Value value, std::string reference_key, Reference reference) {
  figure.student = decimate(mine, value, figure);
  figure.reference_key = std::move(reference_key);
  RunFigure shape;  // how the reference's series is plotted: as the student's
  shape.plotted = figure.plotted, shape.judged_from = figure.judged_from;
  figure.make_reference = [reference, value, shape] { return decimate(reference(), value, shape); };
  return figure;
}

}  // namespace opspace::grading
