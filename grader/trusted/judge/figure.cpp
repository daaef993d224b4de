#include "judge/figure.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace opspace::grading {

double plotted_statistic(const RunFigure& f, const Series& s) {
  if (s.v.empty() || f.plotted == Plotted::kSeries) return std::numeric_limits<double>::quiet_NaN();
  if (f.plotted != Plotted::kLargest) return s.v.back();
  double largest = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < s.t.size() && k < s.v.size(); ++k)
    if (s.t[k] >= f.judged_from) largest = std::isnan(s.v[k]) ? s.v[k] : std::max(largest, s.v[k]);
  return largest;
}

}  // namespace opspace::grading
