/// @file visuals/visuals.hpp
/// What a program leaves after its run besides the CSV log: the plots (plot.hpp) and the 3D
/// replay page (replay.hpp), named after the log, their paths printed. Called once the run
/// is over, so that the control loop never waits on it.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "opspace/model/model.hpp"
#include "opspace/visuals/plot.hpp"
#include "opspace/visuals/replay.hpp"

namespace opspace::visuals {

/// "out/hw2-p1-part3.csv" -> "out/hw2-p1-part3": the stem every picture of a run starts with.
std::string prefix_of(const std::string& csv_path);

/// The values `f(sample)` of every sample of a run (`result.samples`), in order: one plotted
/// column.
template <class Result, class F>
std::vector<double> column(const Result& result, F f) {
  std::vector<double> out;
  out.reserve(result.samples.size());
  for (const auto& sample : result.samples) out.push_back(f(sample));
  return out;
}

/// The torques `tau` of every sample of a run, as torque_figure() takes them.
template <class Result>
std::vector<Eigen::VectorXd> torques(const Result& result) {
  std::vector<Eigen::VectorXd> tau;
  tau.reserve(result.samples.size());
  for (const auto& sample : result.samples) tau.emplace_back(sample.tau);
  return tau;
}

/// One panel per joint: the torques tau[k](i) requested at times t[k] against the joint's
/// URDF effort limit (a figure every problem draws).
plot::Figure torque_figure(const Model& model, const std::vector<double>& t,
                           const std::vector<Eigen::VectorXd>& tau, const std::string& who);

/// Files written by publish().
struct Published {
  std::vector<std::string> images;  ///< PNG and SVG plots
  std::string page;                 ///< the replay page, or empty
  std::vector<std::string> skipped; ///< why something was not made (no gnuplot, no bundle)
};

/// Draws `figures` as PREFIX-FIGURE.png/.svg and, when `scene` is given, writes
/// PREFIX-replay.html; prints "plot:   PATH", "replay: PATH" and any "note: ..." lines to
/// `out`. A missing gnuplot or viewer bundle, or a picture that cannot be written, is a
/// note, never an error: this function does not throw.
Published publish(const std::vector<plot::Figure>& figures, const replay::Scene* scene,
                  const std::string& prefix, std::ostream& out);

}  // namespace opspace::visuals
