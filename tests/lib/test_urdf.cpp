// URDF loading: the shipped robots load with the structure their files declare; fixed joints
// merge mass into the parent body and keep their frames; and every kind of broken file is
// refused with a UrdfError that names the file, the line where known, and the cause.
#include <doctest/doctest.h>

#include <pthread.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/model/urdf.hpp"

using namespace opspace;

namespace {

std::string broken(const std::string& name) { return std::string(OPSPACE_TEST_DATA_DIR) + "/urdf/" + name; }

/// The message of the UrdfError that loading `path` throws ("" if none is thrown).
std::string load_error(const std::string& path) {
  try {
    load_urdf(path);
  } catch (const UrdfError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("the shipped robots load with the joints their files declare") {
  struct Expected {
    const char* file;
    const char* name;
    int dof;
    const char* first_joint;
    const char* last_link;
  };
  // Counts and names read off robots/*.urdf (and robots.md's tables).
  const Expected table[] = {{"pp.urdf", "pp", 2, "d1", "link2"},
                            {"puma.urdf", "puma", 6, "shoulder-yaw", "end-effector"},
                            {"iiwa7.urdf", "iiwa7", 7, "j1", "link7"},
                            {"rrr.urdf", "rrr", 3, "joint1", "link3"}};
  for (const Expected& e : table) {
    CAPTURE(e.file);
    const Model model = load_urdf(robot_path(e.file));
    CHECK(model.name == e.name);
    CHECK(model.dof() == e.dof);
    CHECK(model.bodies.front().joint_name == e.first_joint);
    CHECK(model.bodies.back().link_name == e.last_link);
    for (int i = 0; i < model.dof(); ++i) {
      CHECK_MESSAGE(model.bodies[i].parent < i, "bodies must be in topological order");
      CHECK(std::abs(model.bodies[i].axis.norm() - 1.0) < 1e-15);
    }
  }
}

TEST_CASE("the PUMA's table values arrive in the model unchanged") {
  // robots.md, PUMA 560 (problem 1b): upper_arm 17.4 kg, COM (0.068, 0.006, -0.016), Iyy 0.524;
  // elbow effort 89.4 N m; limits +-3.14159; the last joint turns about x.
  const Model model = load_urdf(robot_path("puma.urdf"));
  const Body& upper = model.bodies[model.joint_id("shoulder-pitch")];
  CHECK(upper.inertia.mass == 17.4);
  CHECK((upper.inertia.com - Eigen::Vector3d(0.068, 0.006, -0.016)).norm() < 1e-15);
  CHECK(upper.inertia.inertia(1, 1) == 0.524);
  CHECK(model.bodies[model.joint_id("elbow")].effort == 89.4);
  CHECK(model.bodies[model.joint_id("elbow")].lower == -3.14159);
  CHECK(model.bodies[model.joint_id("wrist-roll2")].axis == Eigen::Vector3d::UnitX());
  CHECK(model.collisions.empty());  // robots.md: no collision shapes
  CHECK(model.visuals.size() == 7);  // one cylinder per link, for drawing
}

TEST_CASE("a fixed joint merges its child's mass into the parent and keeps its frame") {
  // A 2 kg link with a 1 kg point mass fixed 0.3 m along its x axis is one body of 3 kg with
  // COM at (2*0 + 1*0.3)/3 = 0.1 and, about that COM, Izz = 0.01 + 2*0.1^2 + 1*0.2^2 = 0.07
  // (parallel axis theorem).
  const char* xml = R"(<robot name="merge">
    <link name="base"/>
    <link name="arm"><inertial><mass value="2"/>
      <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
    <link name="weight"><inertial><mass value="1"/>
      <inertia ixx="0" iyy="0" izz="0" ixy="0" ixz="0" iyz="0"/></inertial>
      <collision><geometry><sphere radius="0.05"/></geometry></collision></link>
    <joint name="j" type="continuous"><parent link="base"/><child link="arm"/>
      <origin xyz="0 0 1"/><axis xyz="0 0 1"/></joint>
    <joint name="bolt" type="fixed"><parent link="arm"/><child link="weight"/>
      <origin xyz="0.3 0 0" rpy="0 0 1.5707963267948966"/></joint>
  </robot>)";
  const Model model = parse_urdf(xml, "merge.urdf");
  REQUIRE(model.dof() == 1);
  const Inertia& in = model.bodies[0].inertia;
  CHECK(in.mass == doctest::Approx(3.0));
  CHECK((in.com - Eigen::Vector3d(0.1, 0, 0)).norm() < 1e-15);
  CHECK(in.inertia(2, 2) == doctest::Approx(0.07));
  // A = Izz about the joint axis = 0.07 + 3 * 0.1^2 = 0.1 (the point mass counts as m r^2).
  Data data(model);
  CHECK(crba(model, data, Eigen::VectorXd::Zero(1))(0, 0) == doctest::Approx(0.1));
  // The weight's frame and its sphere ride on body 0 at the bolt's placement.
  const Frame& weight = model.frames[model.frame_id("weight")];
  CHECK(weight.body == 0);
  CHECK((weight.placement.translation() - Eigen::Vector3d(0.3, 0, 0)).norm() < 1e-15);
  REQUIRE(model.collisions.size() == 1);
  CHECK(model.collisions[0].kind == Shape::Kind::kSphere);
  CHECK(model.collisions[0].body == 0);
  CHECK(model.collisions[0].link == "weight");
  // A continuous joint has no position limits.
  CHECK(std::isinf(model.bodies[0].upper));
}

TEST_CASE("an axis with huge components is normalized without overflow") {
  // Found by fuzzing (docs/fuzzing.md): |(0, 1e308, 0)|^2 overflows, so the axis divided by its
  // norm became (0, 0, 0). Its direction is +y, like any positive multiple of (0, 1, 0).
  const Model model = parse_urdf(R"(<robot name="r"><link name="base"/><link name="arm"/>
    <joint name="j" type="continuous"><parent link="base"/><child link="arm"/><axis xyz="0 1e308 0"/></joint>
  </robot>)", "<string>");
  CHECK(model.bodies[0].axis == Eigen::Vector3d::UnitY());
}

TEST_CASE("unknown links and joints are refused with their name and the model's") {
  const Model model = load_urdf(robot_path("rrr.urdf"));
  CHECK_THROWS_WITH_AS(model.frame_id("gripper"), doctest::Contains("no link 'gripper' in model 'rrr'"),
                       std::out_of_range);
  CHECK_THROWS_WITH_AS(model.joint_id("ee"), doctest::Contains("no moving joint 'ee' in model 'rrr'"),
                       std::out_of_range);
}

TEST_CASE("each broken URDF is refused with its file, line and cause") {
  struct Case {
    const char* file;
    const char* message;  // what() after "<path>"
  };
  // The line numbers are those the files' comments point at.
  const Case table[] = {
      {"does_not_exist.urdf", ": cannot open the file (No such file or directory)"},
      {"empty.urdf", ": malformed XML: Error document empty."},
      {"malformed_xml.urdf", ":6: malformed XML: Error reading end tag."},
      {"not_a_robot.urdf", ":3: the document element must be <robot>"},
      {"unnamed_robot.urdf", ":3: the <robot> has no name"},
      {"unknown_joint_type.urdf", ":6: joint 'shoulder' has unknown type 'rotational'"},
      {"floating.urdf", ":6: joint 'free' is floating: not supported"},
      {"planar.urdf", ":6: joint 'slide' is planar: not supported"},
      {"mimic.urdf", ":14: joint 'finger2' mimics joint 'finger1': mimic joints are not supported"},
      {"loop.urdf", ":18: link 'c' is the child of both joint 'j2' and joint 'j3': a loop"},
      {"second_root.urdf", ":6: second root link: links 'base' and 'stray' are both without a parent joint"},
      {"cycle.urdf", ":6: link 'a' cannot be reached from the root 'base': its joints form a loop"},
      {"undeclared_link.urdf", ":5: joint 'j1' refers to link 'arm', which is not declared"},
      {"negative_mass.urdf", ":5: link 'arm' has mass -2 kg; a mass must be >= 0"},
      {"indefinite_inertia.urdf", ":6: link 'arm' has an inertia that is not positive semi-definite"},
      {"indefinite_huge_inertia.urdf", ":6: link 'arm' has an inertia that is not positive semi-definite"},
      // urdfdom's messages give no line: the line is that of the joint or link they name.
      {"missing_limit.urdf", ":6: urdfdom rejected the file: Joint [j1] is of type REVOLUTE but it does not specify limits"},
      // Found by fuzzing (docs/fuzzing.md): values urdfdom accepts that the model cannot use.
      {"negative_effort.urdf", ":6: joint 'j1' has effort -0.1 and velocity 10; both limits must be >= 0"},
      {"inverted_limits.urdf", ":5: joint 'j1' has its lower limit 0.5 above its upper limit -0.5"},
      {"negative_radius.urdf", ":5: link 'arm' has a sphere of radius -0.1: sizes must be >= 0"},
      {"placement_overflow.urdf", ":12: joint 'j2' has a placement that overflows (is not finite)"},
      {"mass_overflow.urdf", ":10: link 'tool' has mass properties that overflow (are not finite)"},
      {"cut_utf8.urdf", ":6: malformed UTF-8 at byte 0xe4 (a URDF is UTF-8 text)"},
  };
  for (const Case& c : table) {
    const std::string path = broken(c.file);
    CAPTURE(path);
    const std::string what = load_error(path);
    CHECK_MESSAGE(what.rfind(path + c.message, 0) == 0, "expected \"", path + c.message, "...\", got \"", what, "\"");
  }
}

namespace {

/// The message of the UrdfError that parsing `xml` throws ("" if none is thrown).
std::string parse_error(const std::string& xml) {
  try {
    parse_urdf(xml, "<string>");
  } catch (const UrdfError& e) {
    return e.what();
  }
  return "";
}

/// A one-link robot whose link holds `inner` (URDF allows unknown elements: urdfdom skips them).
std::string robot_with(const std::string& inner) {
  return "<robot name=\"r\">\n<link name=\"base\">" + inner + "</link>\n</robot>";
}

/// `depth` nested <x> elements.
std::string nested(int depth) {
  std::string open, close;
  for (int i = 0; i < depth; ++i) {
    open += "<x>";
    close += "</x>";
  }
  return open + close;
}

/// An element with `count` attributes.
std::string with_attributes(int count) {
  std::string e = "<x";
  for (int i = 0; i < count; ++i) e += " a" + std::to_string(i) + "=\"1\"";
  return e + "/>";
}

}  // namespace

TEST_CASE("nesting and attribute counts that the XML parsers pay for with stack or time are refused") {
  // TinyXML recurses once per nesting level (100000 levels overflowed the stack) and compares
  // each attribute with the element's others (100000 attributes took 170 s): check_markup caps
  // both at 100 before any parser runs. <robot> and <link> are 2 levels, so 98 more reach 100.
  CHECK(parse_error(robot_with(nested(98))).empty());
  CHECK(parse_error(robot_with(nested(99))) == "<string>:2: elements nested more than 100 deep (a URDF nests about 5)");
  CHECK(parse_error(robot_with(with_attributes(100))).empty());
  CHECK(parse_error(robot_with(with_attributes(101))) ==
        "<string>:2: an element with more than 100 attributes (a URDF element has at most 6)");
  // Comments and CDATA hold no tags; in a quoted value '=' is no attribute, '>' no tag's end.
  CHECK(parse_error(robot_with("<!-- " + nested(200) + " --><![CDATA[" + nested(200) + "]]><x v=\"" +
                               std::string(200, '=') + ">\"/>"))
            .empty());
}

TEST_CASE("text that is not UTF-8, or holds a NUL byte, is refused at its line") {
  // TinyXML reads the text as UTF-8 and steps over a character by the length its lead byte
  // announces: 0xe4 announces three bytes, 0xe9 (Latin-1 e-acute) three. A NUL ends the text
  // for both parsers, hiding what follows it.
  const std::string robot = "<robot name=\"r\">\n<link name=\"base\"/>\n</robot>\n";
  CHECK(parse_error(robot + "<!-- caf\xc3\xa9, 12 \xc2\xb0, \xf0\x9f\xa4\x96 -->").empty());  // UTF-8: accepted
  CHECK(parse_error(robot + "<!-- caf\xe9 -->") == "<string>:4: malformed UTF-8 at byte 0xe9 (a URDF is UTF-8 text)");
  CHECK(parse_error(robot + "\xe4\xb8") == "<string>:4: malformed UTF-8 at byte 0xe4 (a URDF is UTF-8 text)");
  CHECK(parse_error(robot + "\xed\xa0\x80") == "<string>:4: malformed UTF-8 at byte 0xed (a URDF is UTF-8 text)");
  CHECK(parse_error(robot + std::string(1, '\0') + "<x/>") == "<string>:4: a NUL byte: a URDF is text");
}

TEST_CASE("control characters of a name are written as hex escapes in the message") {
  // Names are the file's text: ESC [31m in a joint name would turn the reader's terminal red.
  const std::string xml = "<robot name=\"r\"><link name=\"base\"/><link name=\"arm\"/><joint name=\"j\x1b[31m\" "
                          "type=\"rotational\"><parent link=\"base\"/><child link=\"arm\"/></joint></robot>";
  CHECK(parse_error(xml) ==
        "<string>:1: joint 'j\\x1b[31m' has unknown type 'rotational' (expected revolute, continuous, prismatic or fixed)");
}

namespace {

/// A chain of `n` links joined by continuous joints along z, 0.1 m apart.
std::string chain(int n) {
  std::string xml = "<robot name=\"chain\">\n<link name=\"l0\"/>\n";
  for (int i = 1; i <= n; ++i) {
    const std::string k = std::to_string(i), parent = std::to_string(i - 1);
    xml += "<link name=\"l" + k + "\"/><joint name=\"j" + k + "\" type=\"continuous\"><parent link=\"l" + parent +
           "\"/><child link=\"l" + k + "\"/><origin xyz=\"0 0 0.1\"/></joint>\n";
  }
  return xml + "</robot>";
}

struct ChainRun {
  int n = 0;
  int dof = -1;
  std::string error;
};

void* load_chain(void* arg) {
  auto* run = static_cast<ChainRun*>(arg);
  try {
    run->dof = parse_urdf(chain(run->n), "<chain>").dof();
  } catch (const std::exception& e) {
    run->error = e.what();
  }
  return nullptr;
}

}  // namespace

TEST_CASE("a long chain of links loads without exhausting the call stack") {
  // Found in review of the fuzzing (docs/fuzzing.md): the links were walked by recursion,
  // two frames per link, and 5000 links overflowed the 8 MB stack under ASan. On a 256 kB
  // stack the recursion failed between 200 and 300 links (release build); the walk with a
  // stack of its own loads 2000 there, as it would any length.
  ChainRun run;
  run.n = 2000;
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, 256 * 1024);
  pthread_t thread;
  REQUIRE(pthread_create(&thread, &attr, &load_chain, &run) == 0);
  pthread_join(thread, nullptr);
  pthread_attr_destroy(&attr);
  CHECK(run.error.empty());
  CHECK(run.dof == 2000);
}

TEST_CASE("a path that is not a URDF file is refused before it fills the memory") {
  // A folder opens but cannot be read.
  CHECK(load_error(OPSPACE_TEST_DATA_DIR) == std::string(OPSPACE_TEST_DATA_DIR) + ": cannot read the file (Is a directory)");
  // load_urdf reads at most 16 MB: one byte more is refused (a sparse file: no disk used). The
  // same bound stops /dev/zero, which filled the memory before; it is not read here, so that
  // a regression fails this test instead of the machine.
  const std::filesystem::path big = std::filesystem::temp_directory_path() / "opspace-test-urdf-17MB.urdf";
  std::ofstream(big).close();
  std::filesystem::resize_file(big, (std::uintmax_t{16} << 20) + 1);
  const std::string what = load_error(big.string());
  std::filesystem::remove(big);
  CHECK(what == big.string() + ": larger than 16 MB: not a URDF (meshes live in files of their own)");
}
