/// @file constants.hpp
/// The library's constants, written once: pi and the degree. The math floor: it includes
/// nothing, and model/, algorithms/, simulation/ and the rest build on it.
#pragma once

namespace opspace {

/// pi, to double precision.
inline constexpr double kPi = 3.14159265358979323846;

/// One degree in radians: `30 * kDeg`, and an angle in degrees is `angle / kDeg`.
inline constexpr double kDeg = kPi / 180.0;

}  // namespace opspace
