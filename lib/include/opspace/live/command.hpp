/// @file live/command.hpp
/// The live page's commands (POST /command, a JSON object; docs/live.md#protocol), read and
/// checked before anything changes: a command that is not exactly right is refused whole.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "opspace/live/lab.hpp"

namespace opspace::live {

/// Largest command body accepted (bytes): a push, the longest command, takes about 120.
inline constexpr std::size_t kMaxCommandBytes = 4096;
/// Largest |coordinate| of a push's points (m): the arms reach about 1 m.
inline constexpr double kMaxPushCoordinate = 10.0;
/// Slow motion down to a tenth of real time, and no faster than real time.
inline constexpr double kMinSpeed = 0.1;
inline constexpr double kMaxSpeed = 1.0;  ///< see kMinSpeed

/// A refused command; what() says why, for the page (HTTP 400).
class CommandError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// One command from the page.
struct Command {
  enum class Kind { kPause, kResume, kReset, kSpeed, kLaw, kGain, kPush, kRelease };
  Kind kind = Kind::kPause;  ///< which command; the members below that apply to it are set
  long long id = 0;          ///< the page's number for it, echoed in the frames
  double value = 0.0;        ///< speed (kMinSpeed..kMaxSpeed), law index, gain value
  int gain = -1;             ///< gain: index into LabInfo::gains
  int body = -1;             ///< push: index into Model::bodies
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< push: picked point, body frame (m)
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  ///< push: where the mouse pulls it, world (m)
};

/// What a command is checked against.
struct CommandLimits {
  int laws = 1;             ///< law indices 0 .. laws - 1
  std::vector<Gain> gains;  ///< names and ranges
  int bodies = 0;           ///< push body indices 0 .. bodies - 1
};

/// Reads `body`, a JSON object {"id": n, "command": "...", ...}. Throws CommandError for a body
/// over kMaxCommandBytes, text that is not JSON, an unknown command or key, a value of the
/// wrong type, a number that is not finite or out of its range.
Command parse_command(std::string_view body, const CommandLimits& limits);

}  // namespace opspace::live
