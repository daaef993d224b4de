#include "run/answer_decoding.hpp"

#include <stdexcept>

#include "run/functions.hpp"
#include "protocol/codec.hpp"

namespace opspace::grading {

AnswerKind check_answer(const protocol::Header& answer, std::uint32_t sequence, std::size_t value_size,
                        std::string& why) {
  if (answer.magic != protocol::kAnswerMagic) {
    why = "your code wrote something that is not an answer on the grader's channel";
    return AnswerKind::kRejected;
  }
  if (answer.sequence != sequence) {
    why = "your code sent an answer to request " + std::to_string(answer.sequence) + " while the grader asked request " +
          std::to_string(sequence);
    return AnswerKind::kRejected;
  }
  switch (static_cast<protocol::Status>(answer.code)) {
    case protocol::Status::kException:
      if (answer.size <= protocol::kMaxExceptionText) return AnswerKind::kException;
      why = "your code sent an exception text longer than allowed";
      return AnswerKind::kRejected;
    case protocol::Status::kValue:
      if (answer.size == value_size) return AnswerKind::kValue;
      why = "your code sent " + std::to_string(answer.size) + " bytes where the answer has " + std::to_string(value_size);
      return AnswerKind::kRejected;
    default:
      why = "your code's runner did not know the function it was asked for";
      return AnswerKind::kRejected;
  }
}

std::size_t answer_size(protocol::Function function) {
  std::size_t size = 0;
  Hw2Api table;
  for_each_function(table, [&](protocol::Function f, auto& slot) {
    using R = typename std::decay_t<decltype(slot)>::result_type;
    if (f == function) size = protocol::encoded_size<R>();
  });
  return size;
}

std::vector<double> decode_answer(protocol::Function function, const std::vector<unsigned char>& bytes) {
  std::vector<double> numbers;
  bool known = false;
  Hw2Api table;
  for_each_function(table, [&](protocol::Function f, auto& slot) {
    using R = typename std::decay_t<decltype(slot)>::result_type;
    if (f != function) return;
    known = true;
    R value{};
    protocol::Reader r(bytes.data(), bytes.size());
    protocol::get(r, value);
    r.finish();
    protocol::flatten(numbers, value);
  });
  if (!known) throw std::invalid_argument("unknown function code");
  return numbers;
}

}  // namespace opspace::grading
