/// @file run_figure.hpp
/// A simulated test's figure (grading.hpp: RunFigure): the series its checks read, from the
/// student's run and from the reference's, the run of the problem set's law (the oracle of the
/// test's law pin) in the same scenario. Decimated to what a plot needs.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <utility>

#include "grading.hpp"

namespace opspace::grading {

/// At most this many points per series: a plot 640 px wide needs no more, and the thirty
/// series of a full grading stay well under 100 KB of page.
inline constexpr std::size_t kFigurePoints = 240;

/// value(s) of every sample s of `samples`, decimated to at most kFigurePoints: the first and
/// the last sample (the run's final value, which the test's replay reproduces), and between
/// them, of each run of consecutive samples, the one of largest |value| (a peak a check reads
/// stays in the plot; a value that is not finite counts as the largest).
template <class Samples, class Value>
Series decimate(const Samples& samples, Value value) {
  Series out;
  const std::size_t n = samples.size();
  if (n == 0) return out;
  out.t.push_back(samples[0].t);
  out.v.push_back(value(samples[0]));
  if (n == 1) return out;
  const std::size_t per = (n + kFigurePoints - 3) / (kFigurePoints - 2);  // leaves room for the first and last
  const auto larger = [](double a, double b) { return !std::isfinite(a) || (std::isfinite(b) && std::abs(a) > std::abs(b)); };
  for (std::size_t first = 1; first + 1 < n; first += per) {
    std::size_t best = first;
    double best_value = value(samples[first]);
    for (std::size_t k = first + 1; k < std::min(first + per, n - 1); ++k) {
      const double v = value(samples[k]);
      if (larger(v, best_value)) best = k, best_value = v;
    }
    out.t.push_back(samples[best].t);
    out.v.push_back(best_value);
  }
  out.t.push_back(samples[n - 1].t);
  out.v.push_back(value(samples[n - 1]));
  return out;
}

/// The figure of `quantity` in the student's run `mine` (its samples), whose reference series
/// is `reference_key` of the reference's run, made by `reference` only when the report needs it
/// (reference_runs.hpp: a passed test's figure shows it when it is known already).
template <class Samples, class Value>
RunFigure run_figure(RunFigure figure, const Samples& mine, Value value, std::string reference_key,
                     std::function<Series()> reference) {
  figure.student = decimate(mine, value);
  figure.reference_key = std::move(reference_key);
  figure.make_reference = std::move(reference);
  return figure;
}

}  // namespace opspace::grading
