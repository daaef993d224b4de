/// @file recording.hpp
/// The calls of a test recorded as they are made (arguments and answers, as the protocol
/// encodes them): what the diagnosis replays to name a mistake (judge/diagnosis.hpp), and what a
/// run made ahead hands to the test that takes it (runs_ahead.hpp).
#pragma once

#include <vector>

#include "protocol/protocol.hpp"
#include "run/api.hpp"

namespace opspace::grading {

/// One call of a student's function during a test.
struct Call {
  protocol::Function function;
  std::vector<unsigned char> arguments;  ///< encoded as the protocol encodes them
  std::vector<unsigned char> answer;     ///< the student's value, encoded
};

/// The calls of one test: the first 32, then every 100th, at most 200 (a simulated run makes
/// thousands; these span it).
struct Recording {
  std::vector<Call> calls;
  long seen = 0;  ///< how many calls were made in all
};

/// A copy of `api` whose functions also record their calls in `recording`.
Hw2Api recorded(const Hw2Api& api, Recording& recording);

}  // namespace opspace::grading
