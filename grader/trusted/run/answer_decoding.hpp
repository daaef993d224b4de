/// @file answer_decoding.hpp
/// The grader's reading of what a runner sends: the checks of an answer's header, and the
/// decoding of its value by the function asked. Everything here takes untrusted bytes; it
/// never allocates more than the header's checked size, and a bad message is a returned or
/// thrown error, never a crash (tests/fuzz/fuzz_protocol.cpp feeds it arbitrary bytes).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "protocol/protocol.hpp"

namespace opspace::grading {

/// What the header says about the answer's payload.
enum class AnswerKind { kValue, kException, kRejected };

/// Checks the header of an answer to request `sequence`, whose value has `value_size` bytes:
/// kValue (then `size` bytes of value follow), kException (`size` bytes of text follow, at
/// most protocol::kMaxExceptionText), or kRejected with `why` in words for the student.
AnswerKind check_answer(const protocol::Header& answer, std::uint32_t sequence, std::size_t value_size,
                        std::string& why);

/// The encoded size of the value `function` returns; 0 for an unknown code.
std::size_t answer_size(protocol::Function function);

/// Decodes `bytes` as the value `function` returns and flattens it to numbers (codec.hpp).
/// Throws protocol::DecodeError if they do not decode, std::invalid_argument for an unknown code.
std::vector<double> decode_answer(protocol::Function function, const std::vector<unsigned char>& bytes);

}  // namespace opspace::grading
