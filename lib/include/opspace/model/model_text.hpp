/// @file model/model_text.hpp
/// A Model as plain text, for programs that cannot read URDF (the explorer's WebAssembly
/// module has no urdfdom): the native side loads the URDF and writes the text; the other side
/// reads it back into the same Model, number for number (17 significant digits round-trip a
/// double exactly).
///
/// Format, one record per line, fields separated by blanks (names percent-encoded, so that a
/// name never holds a blank; `%-` is the empty name). A placement is 12 numbers: the rotation
/// row by row, then the translation.
///   opspace-model 1
///   robot NAME
///   gravity GX GY GZ
///   base MASS CX CY CZ I(3x3 row by row)
///   body JOINT LINK revolute|prismatic PARENT PLACEMENT AX AY AZ MASS CX CY CZ I(9) LOWER UPPER EFFORT VELOCITY
///   armature BODY VALUE         (only for a body whose Body::armature is not 0)
///   frame NAME BODY PLACEMENT
///   visual|collision LINK BODY box|cylinder|sphere SX SY SZ RADIUS LENGTH PLACEMENT
///   end
#pragma once

#include <string>

#include "opspace/model/model.hpp"

namespace opspace {

/// The text of `model` (see the file comment).
std::string write_model_text(const Model& model);

/// The Model written by write_model_text. `source` names the text in error messages. Throws
/// std::invalid_argument "SOURCE:LINE: what is wrong" for text that is not a Model the URDF
/// loader could have made: an unknown record, a missing or non-finite number (joint limits may
/// be inf or -inf), a parent that does not come first, a body index out of range, a placement
/// that is not a rigid transform, a joint axis that is not a unit vector, limits out of order, a
/// negative mass, size, effort or velocity, an inertia that is not symmetric positive
/// semi-definite, or no `end`.
Model read_model_text(const std::string& text, const std::string& source);

}  // namespace opspace
