// The live page's commands, read and checked (live/command.hpp).
#include "opspace/live/command.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

namespace opspace::live {

namespace {

using Json = nlohmann::json;

struct Spec {
  const char* name;
  Command::Kind kind;
  std::set<std::string> keys;  // besides "id" and "command"
};

const Spec kSpecs[] = {
    {"pause", Command::Kind::kPause, {}},
    {"resume", Command::Kind::kResume, {}},
    {"reset", Command::Kind::kReset, {}},
    {"speed", Command::Kind::kSpeed, {"value"}},
    {"law", Command::Kind::kLaw, {"value"}},
    {"gain", Command::Kind::kGain, {"name", "value"}},
    {"push", Command::Kind::kPush, {"body", "point", "target"}},
    {"release", Command::Kind::kRelease, {}},
};

[[noreturn]] void refuse(const std::string& why) { throw CommandError(why); }

double number(const Json& j, const char* key) {
  const Json& v = j.at(key);
  if (!v.is_number()) refuse(std::string("'") + key + "' must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) refuse(std::string("'") + key + "' must be finite");
  return x;
}

// A whole number in [0, count): JSON numbers like 2.0 are accepted, 2.5 is not.
int index(const Json& j, const char* key, int count, const char* what) {
  const double x = number(j, key);
  if (x != std::floor(x) || x < 0.0 || x >= count) {
    refuse(std::string("'") + key + "' must be a " + what + " index from 0 to " + std::to_string(count - 1));
  }
  return static_cast<int>(x);
}

Eigen::Vector3d point(const Json& j, const char* key) {
  const Json& v = j.at(key);
  if (!v.is_array() || v.size() != 3) refuse(std::string("'") + key + "' must be an array of 3 numbers");
  Eigen::Vector3d p;
  for (int i = 0; i < 3; ++i) {
    if (!v[i].is_number()) refuse(std::string("'") + key + "' must be an array of 3 numbers");
    p(i) = v[i].get<double>();
    if (!std::isfinite(p(i)) || std::abs(p(i)) > kMaxPushCoordinate) {
      refuse(std::string("'") + key + "' must have finite coordinates within " + std::to_string(int(kMaxPushCoordinate)) + " m");
    }
  }
  return p;
}

}  // namespace

Command parse_command(std::string_view body, const CommandLimits& limits) {
  if (body.size() > kMaxCommandBytes) refuse("the command is longer than " + std::to_string(kMaxCommandBytes) + " bytes");
  const Json j = Json::parse(body.begin(), body.end(), nullptr, false);
  if (j.is_discarded()) refuse("the command is not JSON");
  if (!j.is_object()) refuse("the command must be a JSON object");
  if (!j.contains("command") || !j["command"].is_string()) refuse("'command' must be a string");
  const std::string name = j["command"].get<std::string>();
  const Spec* spec = nullptr;
  for (const Spec& s : kSpecs) spec = name == s.name ? &s : spec;
  if (spec == nullptr) refuse("unknown command '" + name.substr(0, 40) + "'");
  for (const auto& item : j.items()) {
    if (item.key() != "id" && item.key() != "command" && spec->keys.count(item.key()) == 0) {
      refuse("'" + name + "' takes no '" + item.key().substr(0, 40) + "'");
    }
  }
  for (const std::string& key : spec->keys) {
    if (!j.contains(key)) refuse("'" + name + "' needs '" + key + "'");
  }
  Command c;
  c.kind = spec->kind;
  if (!j.contains("id")) refuse("'id' is missing");
  const double id = number(j, "id");
  if (id != std::floor(id) || id < 0.0 || id > 9007199254740992.0) refuse("'id' must be a whole number from 0 to 2^53");
  c.id = static_cast<long long>(id);
  switch (c.kind) {
    case Command::Kind::kSpeed:
      c.value = number(j, "value");
      if (c.value < kMinSpeed || c.value > kMaxSpeed) refuse("'speed' must be from 0.1 to 1 (times real time)");
      break;
    case Command::Kind::kLaw: c.value = index(j, "value", limits.laws, "law"); break;
    case Command::Kind::kGain: {
      if (!j["name"].is_string()) refuse("'name' must be a string");
      const std::string gain = j["name"].get<std::string>();
      for (std::size_t i = 0; i < limits.gains.size(); ++i) c.gain = limits.gains[i].name == gain ? int(i) : c.gain;
      if (c.gain < 0) refuse("unknown gain '" + gain.substr(0, 40) + "'");
      const Gain& g = limits.gains[c.gain];
      c.value = number(j, "value");
      if (c.value < g.min || c.value > g.max) {
        refuse("'" + g.name + "' must be from " + std::to_string(g.min) + " to " + std::to_string(g.max));
      }
      break;
    }
    case Command::Kind::kPush:
      c.body = index(j, "body", limits.bodies, "body");
      c.point = point(j, "point");
      c.target = point(j, "target");
      break;
    default: break;
  }
  return c;
}

}  // namespace opspace::live
