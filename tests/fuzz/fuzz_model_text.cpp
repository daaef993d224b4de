// libFuzzer target: read_model_text() (lib/src/model/model_text.cpp), which reads a Model written
// as text (the explorer's page hands each robot to its WebAssembly module this way). Each input must
// either give a Model whose every number is usable (fuzz::check_model) and whose text reads back
// to the same text, or be refused with std::invalid_argument "fuzz.model:<line>: <cause>", the
// line one of the input's (0 for an input without lines), no control character in it. Any other
// exception, a sanitizer report, a hang (-timeout) or a large allocation (-malloc_limit_mb) is a
// finding. Seeds: tests/fuzz/seeds/model-text (the four robots' texts); dictionary:
// model_text.dict.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "opspace/model/model_text.hpp"

#include "model_checks.hpp"

namespace {

using fuzz::require;

const char kSource[] = "fuzz.model";

/// Lines of `text` as std::getline counts them: each '\n' ends one, and a last line may lack it.
long lines(const std::string& text) {
  long n = 0;
  for (const char c : text) n += c == '\n' ? 1 : 0;
  return n + (!text.empty() && text.back() != '\n' ? 1 : 0);
}

/// "fuzz.model:<line>: <cause>": the line one of the input's, a cause, no control character.
void check_refusal(const std::string& what, const std::string& text) {
  const std::string prefix = std::string(kSource) + ":";
  require(what.rfind(prefix, 0) == 0, "error does not name the text: " + what);
  for (const char c : what) require(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f, "control character in: " + what);
  const std::size_t cause = what.find(": ", prefix.size());
  require(cause != std::string::npos && what.size() > cause + 2, "error without a cause: " + what);
  const std::string digits = what.substr(prefix.size(), cause - prefix.size());
  require(!digits.empty() && digits.size() < 10 && digits.find_first_not_of("0123456789") == std::string::npos,
          "line is not a number: " + what);
  const long line = std::stol(digits);
  require(line >= 0 && line <= lines(text), "line outside the input: " + what);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  opspace::Model model;
  try {
    model = opspace::read_model_text(text, kSource);
  } catch (const std::invalid_argument& e) {
    check_refusal(e.what(), text);
    return 0;
  }
  fuzz::check_model(model);
  // What was accepted is a Model the writer can hand on: its text reads back to the same text.
  const std::string written = opspace::write_model_text(model);
  std::string again;
  try {
    again = opspace::write_model_text(opspace::read_model_text(written, "written"));
  } catch (const std::invalid_argument& e) {
    require(false, std::string("the text of an accepted Model is refused: ") + e.what());
  }
  require(again == written, "the text of an accepted Model does not read back to itself");
  return 0;
}
