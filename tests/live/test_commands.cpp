// The live page's commands are read whole or refused whole (lib/src/live/command.cpp).
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "opspace/live/command.hpp"

using opspace::live::Command;
using opspace::live::CommandError;
using opspace::live::CommandLimits;
using opspace::live::parse_command;

namespace {

CommandLimits limits() {
  CommandLimits l;
  l.laws = 3;
  l.gains = {{"kpx", "kp", 10.0, 200.0, 50.0}};
  l.bodies = 6;
  return l;
}

// The message of the refusal of `body`, or "" if it was accepted.
std::string refusal(const std::string& body) {
  try {
    parse_command(body, limits());
  } catch (const CommandError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a well-formed command of each kind is read with its values") {
  CHECK(parse_command(R"({"id":1,"command":"pause"})", limits()).kind == Command::Kind::kPause);
  CHECK(parse_command(R"({"id":2,"command":"resume"})", limits()).kind == Command::Kind::kResume);
  CHECK(parse_command(R"({"id":3,"command":"reset"})", limits()).kind == Command::Kind::kReset);
  CHECK(parse_command(R"({"id":4,"command":"release"})", limits()).kind == Command::Kind::kRelease);
  const Command speed = parse_command(R"({"id":5,"command":"speed","value":0.25})", limits());
  CHECK(speed.value == 0.25);
  CHECK(speed.id == 5);
  CHECK(parse_command(R"({"id":6,"command":"law","value":2})", limits()).value == 2.0);
  const Command gain = parse_command(R"({"id":7,"command":"gain","name":"kpx","value":120})", limits());
  CHECK(gain.gain == 0);
  CHECK(gain.value == 120.0);
  const Command push = parse_command(R"({"id":8,"command":"push","body":2,"point":[0,0.1,0],"target":[0.5,0.2,0.3]})", limits());
  CHECK(push.body == 2);
  CHECK(push.point.y() == 0.1);
  CHECK(push.target.z() == 0.3);
}

TEST_CASE("a command that is not exactly right is refused, with what is wrong") {
  CHECK_MESSAGE(refusal("not json").find("not JSON") != std::string::npos, "text that is not JSON");
  CHECK_MESSAGE(refusal("[1,2]").find("JSON object") != std::string::npos, "an array instead of an object");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"explode"})").find("unknown command") != std::string::npos,
                "an unknown command");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"pause","value":1})").find("takes no 'value'") != std::string::npos,
                "an argument the command does not take");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"speed"})").find("needs 'value'") != std::string::npos,
                "a missing argument");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"speed","value":"fast"})").find("must be a number") != std::string::npos,
                "a string where a number belongs");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"speed","value":NaN})").find("not JSON") != std::string::npos,
                "NaN is not JSON");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"speed","value":1e999})").find("not JSON") != std::string::npos,
                "a number beyond a double's range: nlohmann-json refuses to read it");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"speed","value":1e300})").find("0.1 to 1") != std::string::npos,
                "a huge number within a double's range is out of the speed's");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"speed","value":5})").find("0.1 to 1") != std::string::npos,
                "a speed faster than real time");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"law","value":3})").find("law index") != std::string::npos,
                "a law past the last (3 laws: 0..2)");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"law","value":1.5})").find("law index") != std::string::npos,
                "a law that is not a whole number");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"gain","name":"kq","value":60})").find("unknown gain") != std::string::npos,
                "an unknown gain");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"gain","name":"kpx","value":1e6})").find("from 10") != std::string::npos,
                "a gain outside its safe range");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"push","body":6,"point":[0,0,0],"target":[0,0,0]})").find("body index") !=
                    std::string::npos,
                "a body the robot does not have (6 bodies: 0..5)");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"push","body":1,"point":[0,0],"target":[0,0,0]})").find("3 numbers") !=
                    std::string::npos,
                "a point with two coordinates");
  CHECK_MESSAGE(refusal(R"({"id":1,"command":"push","body":1,"point":[0,0,0],"target":[0,0,1e9]})").find("within") !=
                    std::string::npos,
                "a target a million kilometres away");
  CHECK_MESSAGE(refusal(R"({"command":"pause"})").find("'id'") != std::string::npos, "no id");
  CHECK_MESSAGE(refusal(R"({"id":-1,"command":"pause"})").find("'id'") != std::string::npos, "a negative id");
  CHECK_MESSAGE(refusal(std::string(opspace::live::kMaxCommandBytes + 1, ' ')).find("longer than") != std::string::npos,
                "a body over the size cap, refused before it is read");
}
