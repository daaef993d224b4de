/// @file live/lab.hpp
/// One problem's closed loop as the live lab drives it (docs/live.md): reset, law and gains
/// changed between ticks, one tick at a time, and what the page shows of each tick.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "opspace/model/model.hpp"
#include "opspace/simulation/simulation.hpp"

namespace opspace::live {

/// A gain the page offers as a slider, within a range that keeps the run stable.
struct Gain {
  std::string name;   ///< as in the problem's Goal, e.g. "kpx"
  std::string label;  ///< the slider's label
  double min = 0.0;   ///< smallest value allowed
  double max = 0.0;   ///< largest value allowed
  double value = 0.0; ///< the problem's own value, restored by a reset
};

/// One line of a live plot.
struct Series {
  std::string label;  ///< legend entry
  std::string color;  ///< "#rrggbb"
};

/// One live plot: the last LabInfo::window seconds of its series.
struct Plot {
  std::string title;            ///< e.g. "tip error"
  std::string unit;             ///< of the values, e.g. "mm"
  std::vector<Series> series;   ///< the values of Lab::plot_values, in this order
};

/// A point drawn in the scene, moved every frame (a target).
struct MarkerInfo {
  std::string name;   ///< key in the frames
  std::string label;  ///< legend entry
  std::string color;  ///< "#rrggbb"
  double radius = 0.02;  ///< sphere radius (m)
};

/// A reference's run drawn faintly beside the live one (docs/live.md, "The ghost"): the tip path
/// of each law, unpushed, from t = 0, sampled every `step` s; the page shows the path of the law
/// in force and a ball where it is at the run's time.
struct Ghost {
  std::string label;  ///< legend entry
  std::string color;  ///< "#rrggbb"
  double step = 0.0;  ///< seconds between points
  std::vector<std::vector<Eigen::Vector3d>> paths;  ///< per law (info().laws' order); empty: none
};

/// What the page shows of a problem, fixed for a session.
struct LabInfo {
  std::string program;   ///< e.g. "hw2-p1": the log's and the terminal's name
  std::string title;     ///< the page's heading
  /// One line under it: what the run shows, measured, never a promise (a student's controller
  /// may not do it). "{K}" stands for the latest value of plot series K (all plots' series in
  /// order, as plot_values), which the page writes in and updates as the run goes.
  std::string subtitle;
  std::string note;      ///< what the physics does, in a few sentences (empty: none)
  std::vector<std::string> laws;  ///< the laws the page can switch between (one: no switch)
  int law = 0;                    ///< the law at the start and after a reset
  std::vector<Gain> gains;        ///< sliders
  std::vector<Plot> plots;        ///< live plots
  std::vector<MarkerInfo> markers;  ///< targets drawn in the scene
  Eigen::Vector3d view = Eigen::Vector3d(1.0, -1.0, 0.7);  ///< camera direction from the scene
  double window = 10.0;           ///< seconds of history the plots show
  Ghost ghost;                    ///< a reference's paths, or none
};

/// A problem's closed loop, driven one tick at a time by a live Session. Between ticks the
/// session may push on the simulation (Simulation::push), change the law or a gain, or reset.
class Lab {
 public:
  virtual ~Lab() = default;
  /// What the page shows; fixed.
  virtual const LabInfo& info() const = 0;
  /// Back to the problem's start: initial state, t = 0, info().law and the gains' values.
  virtual void reset() = 0;
  /// The simulation the loop steps (rebuilt by reset()).
  virtual Simulation& simulation() = 0;
  /// The same, to read (time, settings).
  virtual const Simulation& simulation() const = 0;
  /// Law `law`, an index into info().laws, from the next tick.
  virtual void set_law(int law) = 0;
  /// Gain info().gains[gain] to `value` from the next tick.
  virtual void set_gain(int gain, double value) = 0;
  /// Observes the state at the simulation's time, runs the controller and checks its torques
  /// (throws what the offline run throws); returns the torques to apply for the next step.
  virtual const Eigen::VectorXd& tick() = 0;
  /// The push applied after this tick as joint torques, Je^T F (zero when there is none), for
  /// what the page predicts of it; it changes nothing in the run.
  virtual void set_push_torque(const Eigen::Ref<const Eigen::VectorXd>& torque) { (void)torque; }
  /// The last tick's values of info().plots' series, all plots in order.
  virtual void plot_values(std::vector<double>& values) const = 0;
  /// The last tick's marker positions (world), in info().markers' order.
  virtual void marker_positions(std::vector<Eigen::Vector3d>& positions) const = 0;
  /// The offline run's CSV columns, and the last tick's row of them.
  virtual std::vector<std::string> csv_columns() const = 0;
  /// See csv_columns().
  virtual std::vector<double> csv_row() const = 0;
};

}  // namespace opspace::live
