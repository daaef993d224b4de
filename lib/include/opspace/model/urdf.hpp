/// @file model/urdf.hpp
/// Model from a URDF file, parsed with urdfdom.
#pragma once

#include <stdexcept>
#include <string>

#include "opspace/model/model.hpp"

namespace opspace {

/// Error in a URDF file; what() reads "<file>:<line>: <cause>", or "<file>: <cause>" where no
/// line is known (a missing file, a rejection by urdfdom that names no joint or link). Control
/// characters of the file's names appear as \xNN.
class UrdfError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads a URDF file. Supports revolute, continuous, prismatic and fixed joints (fixed
/// children are merged into their parent body, their frames kept). Throws UrdfError for a
/// missing or unreadable file or one over 16 MB, text that is not UTF-8 or holds a NUL byte,
/// malformed XML, elements nested more than 100 deep or with more than 100 attributes, an
/// unsupported joint (floating, planar, mimic), a loop or a second root, a negative mass, an
/// inertia that is not positive semi-definite, a lower limit above the upper one, a negative
/// effort or velocity limit, a negative shape size, or numbers whose sums or products
/// overflow (docs/model.md, docs/fuzzing.md).
Model load_urdf(const std::string& path);

/// The same from URDF text (load_urdf reads the file, then calls it); `source` names the text
/// in error messages, e.g. "<string>".
Model parse_urdf(const std::string& xml, const std::string& source);

/// Absolute path of a robot model shipped in robots/ (e.g. "puma.urdf").
std::string robot_path(const std::string& file_name);

}  // namespace opspace
