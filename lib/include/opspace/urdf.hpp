/// @file urdf.hpp
/// Model from a URDF file, parsed with urdfdom.
#pragma once

#include <stdexcept>
#include <string>

#include "opspace/model.hpp"

namespace opspace {

/// Error in a URDF file; what() reads "<file>:<line>: <cause>", or "<file>: <cause>" where no
/// line is known (a missing file, a rejection by urdfdom itself).
class UrdfError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads a URDF file. Supports revolute, continuous, prismatic and fixed joints (fixed
/// children are merged into their parent body, their frames kept). Throws UrdfError for a
/// missing file, malformed XML, an unsupported joint (floating, planar, mimic), a loop or a
/// second root, a negative mass or an inertia that is not positive definite.
Model load_urdf(const std::string& path);

/// The same from URDF text; `source` names it in error messages.
Model parse_urdf(const std::string& xml, const std::string& source);

/// Absolute path of a robot model shipped in robots/ (e.g. "puma.urdf").
std::string robot_path(const std::string& file_name);

}  // namespace opspace
