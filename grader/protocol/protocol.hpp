/// @file protocol.hpp
/// The messages between the grader (trusted) and a runner (untrusted): the only thing the two
/// sides share. Both compile this header; neither trusts what the other sends.
///
/// A request is a Header {kRequestMagic, sequence, function, size} and `size` bytes of
/// arguments; the answer is a Header {kAnswerMagic, sequence, status, size} and `size` bytes:
/// the encoded return value (Status::kValue), or the text of an exception (Status::kException).
/// Values are encoded in the machine's byte order (both sides run on one machine): double as 8
/// bytes, int as 4, bool as one byte 0 or 1, fixed-size Eigen matrices column by column, and
/// the problem set's structs field by field (codec.hpp). The runner reads requests on fd
/// kRequestFd and answers on kAnswerFd; its stdout and stderr are the student's prints.
#pragma once

#include <cstdint>

namespace opspace::protocol {

inline constexpr std::uint32_t kRequestMagic = 0x5152534fu;  ///< "OSRQ"
inline constexpr std::uint32_t kAnswerMagic = 0x5352534fu;   ///< "OSRS"
/// No message of the problem set is larger than a few kilobytes; 64 KiB bounds every read.
inline constexpr std::uint32_t kMaxPayload = 1u << 16;
/// The text of an exception is cut to this many bytes by the runner and again by the grader.
inline constexpr std::uint32_t kMaxExceptionText = 400;
inline constexpr int kRequestFd = 3;  ///< the runner reads requests here
inline constexpr int kAnswerFd = 4;   ///< the runner writes answers here

/// The fixed-size start of every message.
struct Header {
  std::uint32_t magic = 0;     ///< kRequestMagic or kAnswerMagic
  std::uint32_t sequence = 0;  ///< the request's number; an answer repeats it
  std::uint32_t code = 0;      ///< a Function (request) or a Status (answer)
  std::uint32_t size = 0;      ///< bytes that follow
};
static_assert(sizeof(Header) == 16, "the header is four 32-bit words");

/// How a runner answered.
enum class Status : std::uint32_t {
  kValue = 0,            ///< the function returned; the payload is its value
  kException = 1,        ///< the function threw; the payload is the exception's text
  kUnknownFunction = 2,  ///< this runner does not serve that function
};

/// Every function a student writes, one code each (problem in the high byte).
enum class Function : std::uint32_t {
  kP1aDegreesOfFreedom = 0x1a01,
  kP1aMassMatrix = 0x1a02,
  kP1aTaskJacobian = 0x1a03,
  kP1aPseudoInverse = 0x1a04,
  kP1aWeightedInverse = 0x1a05,
  kP1aInertiaWeightedInverse = 0x1a06,
  kP1aNullspaceProjector = 0x1a07,
  kP1aInverseKinematicsStep = 0x1a08,
  kP1aSplitDisplacement = 0x1a09,
  kP1bControl = 0x1b01,
  kP2DesiredAcceleration = 0x0201,
  kP2DesiredTwistAcceleration = 0x0202,
  kP2Control = 0x0203,
  kP3MotionSelection = 0x0301,
  kP3ForceSelection = 0x0302,
  kP3Control = 0x0303,
  kP4DegreesOfFreedom = 0x0401,
  kP4SingularDirections = 0x0402,
  kP4MovingDirections = 0x0403,
  kP4RotationAxes = 0x0404,
  kP4SingularityType = 0x0405,
  kP4Control = 0x0406,
};

}  // namespace opspace::protocol
