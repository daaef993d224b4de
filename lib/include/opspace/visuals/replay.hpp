/// @file visuals/replay.hpp
/// A 3D replay of a run: one self-contained HTML page that animates the logged joint motion
/// with the robot drawn from its URDF visual shapes, plus markers (desired targets, the tip's
/// path, force arrows, contact planes). The viewer is three.js bundled at build time (web/),
/// inlined into the page, so the page opens offline. Body poses are computed here, in C++,
/// with forward_kinematics, after the run: the page only plays them back.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "opspace/model/model.hpp"

namespace opspace::replay {

/// A 3D vector per logged sample (same length as Scene::t), or one vector for a constant.
using Track = std::vector<Eigen::Vector3d>;

/// Something drawn besides the robot. Build one with the factory functions.
struct Marker {
  enum class Kind { kPoint, kTrail, kArrow, kPlane };
  Kind kind = Kind::kPoint;  ///< which of the members below apply (see each one)
  std::string label;  ///< legend entry; empty: not listed
  std::string color = "#e74c3c";  ///< "#rrggbb"
  Track positions;    ///< point, trail: where; arrow: its origin
  Track vectors;      ///< arrow: the vector drawn (scaled by `scale`)
  double radius = 0.015;  ///< point (m)
  double scale = 1.0;     ///< arrow: metres drawn per unit of the vector (e.g. m per N)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< plane: a point on it
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); ///< plane: its normal
  double size = 1.0;      ///< plane: edge of the square drawn (m)

  /// A sphere at `where` (a target: constant or moving).
  static Marker point_at(std::string label, std::string color, Track where, double radius = 0.015);
  /// The path of a point, drawn up to the current time.
  static Marker trail(std::string label, std::string color, Track where);
  /// An arrow from `origins` along `vectors` * scale (a force: scale in m/N).
  static Marker arrow(std::string label, std::string color, Track origins, Track vectors, double scale);
  /// A square patch of a plane (a contact surface).
  static Marker plane(std::string label, std::string color, const Eigen::Vector3d& point,
                      const Eigen::Vector3d& normal, double size);
};

/// A named number shown over the scene, one value per logged sample.
struct Readout {
  std::string label;           ///< shown before the value, with its unit, e.g. "F_x (N)"
  std::vector<double> values;  ///< one per entry of Scene::t
};

/// Everything the page shows.
struct Scene {
  std::string title;     ///< the page's title and heading
  std::string subtitle;  ///< one line under the heading; empty: none
  Model model;                       ///< its visuals are drawn; its kinematics place them
  std::vector<double> t;             ///< logged times (s), increasing
  std::vector<Eigen::VectorXd> q;    ///< joint positions, one per entry of t
  std::vector<Marker> markers;       ///< drawn besides the robot, listed in the legend
  std::vector<Readout> readouts;     ///< head-up numbers, after the time
  Eigen::Vector3d view = Eigen::Vector3d(1.0, -1.0, 0.7);  ///< camera direction from the scene
  double fps = 50.0;                 ///< frames kept per simulated second
};

/// What write() did.
struct Output {
  std::string page;     ///< the HTML written, or empty
  std::string skipped;  ///< empty, or why no page was written
};

/// The bundled viewer script: $OPSPACE_REPLAY_BUNDLE if set, else the one built by CMake
/// (build/PRESET/web/opspace-replay.js).
std::string bundle_path();

/// The frames kept at `fps` out of logged times t (indices into t; always the first and last).
std::vector<std::size_t> frame_indices(const std::vector<double>& t, double fps);

/// The data block of the page (JSON): shapes, per-frame body poses, markers, readouts.
/// Throws std::invalid_argument when the scene's vectors disagree in length.
std::string scene_json(const Scene& scene);

/// Writes the page at `html_path` (creating its folder). A missing bundle is reported in
/// Output::skipped, never thrown; a page that cannot be written throws std::runtime_error.
Output write(const Scene& scene, const std::string& html_path);

}  // namespace opspace::replay
