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

#include "problems.hpp"

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

/// Every function a student writes, one code each, from the problems' tables (problems.hpp):
/// kP1aDegreesOfFreedom = 0x1a01 ... kP4Control = 0x0406, the problem's byte high.
enum class Function : std::uint32_t {
#define OPSPACE_FUNCTION_CODE(problem, code, Code, name) Code = code,
  OPSPACE_FUNCTIONS(OPSPACE_FUNCTION_CODE)
#undef OPSPACE_FUNCTION_CODE
};

/// Every function, in the tables' order.
inline constexpr Function kFunctions[] = {
#define OPSPACE_FUNCTION_ENUMERATOR(problem, code, Code, name) Function::Code,
    OPSPACE_FUNCTIONS(OPSPACE_FUNCTION_ENUMERATOR)
#undef OPSPACE_FUNCTION_ENUMERATOR
};

/// Each code carries its problem's byte (and a switch over them, functions.hpp's function_name,
/// refuses two equal codes).
namespace problem_byte {
#define OPSPACE_PROBLEM_BYTE(arg, problem, Problem, key, byte, FUNCTIONS) inline constexpr std::uint32_t problem = byte;
OPSPACE_PROBLEMS(OPSPACE_PROBLEM_BYTE, ~)
#undef OPSPACE_PROBLEM_BYTE
}  // namespace problem_byte
#define OPSPACE_CHECK_CODE(problem, code, Code, name) \
  static_assert((code) >> 8 == problem_byte::problem, #Code "'s code does not carry its problem's byte");
OPSPACE_FUNCTIONS(OPSPACE_CHECK_CODE)
#undef OPSPACE_CHECK_CODE

}  // namespace opspace::protocol
