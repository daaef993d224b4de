// libFuzzer target: the live page's commands (lib/src/live/command.cpp), the parser a web page
// talks to. Every input must be refused with CommandError, or read into a command whose values
// all lie within the limits it was checked against: no other exception, no crash, no value out
// of range. Seeds: seeds/live-command/*.json.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "opspace/live/command.hpp"

namespace {

using opspace::live::Command;

void require(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz-live-command: %s\n", what);
  std::abort();
}

bool within(const Eigen::Vector3d& p) {
  return p.allFinite() && p.cwiseAbs().maxCoeff() <= opspace::live::kMaxPushCoordinate;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  opspace::live::CommandLimits limits;
  limits.laws = 3;
  limits.gains = {{"kpx", "kp", 10.0, 200.0, 50.0}, {"kvj", "kv", 0.0, 60.0, 20.0}};
  limits.bodies = 6;
  const std::string body(reinterpret_cast<const char*>(data), size);
  try {
    const Command c = opspace::live::parse_command(body, limits);
    require(body.size() <= opspace::live::kMaxCommandBytes, "a body over the cap was read");
    require(c.id >= 0, "a negative id was accepted");
    switch (c.kind) {
      case Command::Kind::kSpeed:
        require(c.value >= opspace::live::kMinSpeed && c.value <= opspace::live::kMaxSpeed, "a speed out of range");
        break;
      case Command::Kind::kLaw: require(c.value >= 0 && c.value < limits.laws && c.value == std::floor(c.value), "a bad law"); break;
      case Command::Kind::kGain:
        require(c.gain >= 0 && c.gain < 2, "a bad gain index");
        require(c.value >= limits.gains[c.gain].min && c.value <= limits.gains[c.gain].max, "a gain out of range");
        break;
      case Command::Kind::kPush:
        require(c.body >= 0 && c.body < limits.bodies, "a bad body");
        require(within(c.point) && within(c.target), "a push point out of range");
        break;
      default: break;
    }
  } catch (const opspace::live::CommandError&) {
    // refused: what must happen to every bad input
  }
  return 0;
}
