// libFuzzer target: the grader's reading of what a runner sends
// (grader/trusted/run/answer_decoding.cpp, student_text.cpp's student_line()): arbitrary bytes as
// the answer to a request.
// Input: one byte choosing the function asked (of protocol::kFunctions, every function in
// the problems' tables' order), then a 16-byte answer header, then the payload.
// check_answer() must accept only a header for request 1 with the exact size of that
// function's value (or an exception text of at most 400 bytes); decode_answer() must decode
// every payload of the right size or refuse it with DecodeError (a true/false byte that is
// neither 0 nor 1); an exception text, as the report shows it, must be one line of printable
// ASCII (everything else escaped) within its limit. Anything else (another exception, a
// sanitizer report, a hang, an allocation the size of a header's claim) is a finding.
// Seeds: tests/fuzz/seeds/protocol (well-formed answers of several functions).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "run/answer_decoding.hpp"
#include "common/student_text.hpp"
#include "protocol/codec.hpp"
#include "run/runner_process.hpp"

namespace {

using opspace::protocol::Function;
using opspace::protocol::kFunctions;

void require(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz-protocol: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace grading = opspace::grading;
  if (size < 1 + sizeof(opspace::protocol::Header)) return 0;
  const Function function = kFunctions[data[0] % (sizeof kFunctions / sizeof kFunctions[0])];
  opspace::protocol::Header header;
  std::memcpy(&header, data + 1, sizeof header);
  const std::vector<unsigned char> payload(data + 1 + sizeof header, data + size);
  const std::size_t value_size = grading::answer_size(function);
  require(value_size > 0, "a function of the table has no answer size");

  std::string why;
  switch (grading::check_answer(header, 1, value_size, why)) {
    case grading::AnswerKind::kRejected:
      require(!why.empty(), "a rejected answer without a reason");
      return 0;
    case grading::AnswerKind::kException: {
      require(header.size <= opspace::protocol::kMaxExceptionText, "an exception text over its limit was accepted");
      const std::string text(payload.begin(), payload.begin() + std::min<std::size_t>(payload.size(), header.size));
      const std::string shown = grading::student_line(text, 200, text.size());
      // The fuzzer's bytes are ASCII or invalid UTF-8 or code points the report escapes, or
      // printable code points above U+009F: a byte below 0x20 or DEL would be a finding.
      for (const char c : shown) {
        const auto u = static_cast<unsigned char>(c);
        require(u >= 0x20 && u != 0x7f, "a control character or a newline reached the report");
      }
      // Each byte shown takes at most 4 characters (\xff), plus the quotes and the cut note.
      require(shown.size() <= 4 * 200 + 64, "an exception text was not cut short");
      // Nor a C1 control (U+0080-9F), a bidirectional override or isolate, U+2028 or U+2029.
      for (std::size_t i = 0; i + 1 < shown.size(); ++i) {
        const auto b0 = static_cast<unsigned char>(shown[i]), b1 = static_cast<unsigned char>(shown[i + 1]);
        require(!(b0 == 0xc2 && b1 >= 0x80 && b1 <= 0x9f), "a C1 control reached the report");
        require(!(b0 == 0xd8 && b1 == 0x9c), "the Arabic letter mark reached the report");
        if (b0 == 0xe2 && b1 == 0x80 && i + 2 < shown.size()) {
          const auto b2 = static_cast<unsigned char>(shown[i + 2]);
          require(!(b2 >= 0xa8 && b2 <= 0xae) && b2 != 0x8e && b2 != 0x8f, "a line separator or bidi mark reached the report");
        }
        if (b0 == 0xe2 && b1 == 0x81 && i + 2 < shown.size()) {
          const auto b2 = static_cast<unsigned char>(shown[i + 2]);
          require(!(b2 >= 0xa6 && b2 <= 0xa9), "a bidi isolate reached the report");
        }
      }
      return 0;
    }
    case grading::AnswerKind::kValue:
      require(header.size == value_size, "an answer of the wrong size was accepted");
      break;
  }
  if (payload.size() < value_size) return 0;  // the grader would wait for the rest, then time out
  const std::vector<unsigned char> value(payload.begin(), payload.begin() + static_cast<std::ptrdiff_t>(value_size));
  try {
    const std::vector<double> numbers = grading::decode_answer(function, value);
    require(!numbers.empty(), "a decoded answer holds no number");
  } catch (const opspace::protocol::DecodeError&) {
    // a true/false byte that is neither 0 nor 1: refused, as it should be
  }
  return 0;
}
