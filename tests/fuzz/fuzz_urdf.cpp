// libFuzzer target: parse_urdf() (lib/src/model/urdf*.cpp: a markup scan, TinyXML, urdfdom, then
// our checks) on arbitrary text. Each input must either give a Model whose every number is usable
// (check_model) or be refused with a UrdfError "fuzz.urdf:<line>: <cause>" or "fuzz.urdf:
// <cause>" (a line of the input, no control character). Any other exception, a sanitizer
// report, a NaN or an infinity in the Model (but the position limits of a continuous joint),
// a hang (-timeout) or a large allocation (-malloc_limit_mb) is a finding.
// Seeds: robots/*.urdf, tests/data/**/*.urdf; dictionary: urdf.dict.
#include <cstddef>
#include <cstdint>
#include <string>

#include "opspace/model/urdf.hpp"

#include "model_checks.hpp"

namespace {

using fuzz::require;

const char kSource[] = "fuzz.urdf";

/// Lines of `text` as TinyXML and most editors count them: "\r\n", "\r" and "\n" each end one.
long lines(const std::string& text) {
  long n = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))) ++n;
  }
  return n;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string xml(reinterpret_cast<const char*>(data), size);
  try {
    fuzz::check_model(opspace::parse_urdf(xml, kSource));
  } catch (const opspace::UrdfError& e) {
    // "fuzz.urdf:<line>: <cause>" or "fuzz.urdf: <cause>", with a cause.
    const std::string what = e.what();
    const std::string prefix = std::string(kSource) + ":";
    require(what.rfind(prefix, 0) == 0, "error does not name the file: " + what);
    for (const char c : what) require(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f, "control character in: " + what);
    const std::size_t cause = what.find(": ", prefix.size() - 1);
    require(cause != std::string::npos && what.size() > cause + 2, "error without a cause: " + what);
    if (cause > prefix.size() - 1) {  // a line number: one of the input's lines
      const std::string digits = what.substr(prefix.size(), cause - prefix.size());
      require(digits.find_first_not_of("0123456789") == std::string::npos && digits.size() < 10,
              "line is not a number: " + what);
      const long line = std::stol(digits);
      require(line >= 1 && line <= lines(xml), "line outside the input: " + what);
    }
  }
  return 0;
}
