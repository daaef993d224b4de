// Problem 1c's pictures (problems/1c/run/pictures.hpp).
#include <problems/1c/run/pictures.hpp>

#include <cmath>
#include <string>

#include <problems/1b/run/pictures.hpp>

namespace opspace::scenarios::p1c {

namespace {

constexpr auto kPart = hw2::p1b::Part::kTipPdWithoutJointDamping;

/// |dq_i| from 1 ms differences of q: the null-space motion that no joint damping takes out.
plot::Figure speeds_figure(const Result& r) {
  plot::Figure f("speeds", "problem 1c: joint speeds, which no joint damping slows");
  plot::Panel& panel = f.panel("|dq_i| from 1 ms differences of q", "rad/s");
  for (int i = 0; i < 6; ++i) {
    plot::Series series;
    series.title = "joint " + std::to_string(i + 1);
    for (std::size_t k = 1; k < r.samples.size(); ++k) {
      const double dt = r.samples[k].t - r.samples[k - 1].t;
      series.x.push_back(r.samples[k].t);
      series.y.push_back(std::abs(r.samples[k].q(i) - r.samples[k - 1].q(i)) / dt);
    }
    panel.series.push_back(std::move(series));
  }
  return f;
}

}  // namespace

std::vector<plot::Figure> figures(const Result& result) {
  std::vector<plot::Figure> out = p1b::figures(result, kPart);
  if (result.samples.size() > 1) out.push_back(speeds_figure(result));
  return out;
}

replay::Scene replay_scene(const Result& result) { return p1b::replay_scene(result, kPart); }

}  // namespace opspace::scenarios::p1c
