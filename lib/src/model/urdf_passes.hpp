// The passes of the URDF loader (urdf.cpp runs them in this order), private to lib/src/model.
#pragma once

#include <map>
#include <string>

#include "opspace/model/model.hpp"

namespace urdf {
class ModelInterface;
}

namespace opspace::urdf_passes {

/// Throws UrdfError "<source>:<line>: <cause>", or "<source>: <cause>" when the line is
/// unknown (line <= 0), the cause's control characters written \xNN (urdf.cpp).
[[noreturn]] void fail(const std::string& source, int line, const std::string& cause);

/// Pass 0 (urdf_text.cpp): the text is UTF-8 without NUL bytes, ...
void check_encoding(const std::string& xml, const std::string& source);
/// ... and its markup nests at most 100 deep, with at most 100 attributes per element.
void check_markup(const std::string& xml, const std::string& source);

/// Line of each link and joint element, from pass 1, and the armature of each joint that has
/// an `<armature>` element (opspace's extension: URDF has no field for a motor's inertia).
struct Lines {
  std::map<std::string, int> link, joint;
  std::map<std::string, double> armature;  ///< joint name -> Jm G^2 (kg m^2 or kg)
};

/// Pass 1 (urdf_structure.cpp): XML well-formedness, supported joints, tree shape. Returns the
/// element lines.
Lines check_structure(const std::string& xml, const std::string& source);
/// The line of the first joint or link that urdfdom's messages name; 0 if none is named.
int line_named_in(const std::string& errors, const Lines& lines);

/// Pass 2 (urdf_build.cpp): `model` (name and source set) gets the bodies, frames, masses and
/// shapes of urdfdom's `tree`, every number checked.
void build_model(Model& model, const urdf::ModelInterface& tree, const Lines& lines);

}  // namespace opspace::urdf_passes
