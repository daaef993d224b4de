// URDF loading: the shipped robots load with the structure their files declare; fixed joints
// merge mass into the parent body and keep their frames; and every kind of broken file is
// refused with a UrdfError that names the file, the line where known, and the cause.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "opspace/dynamics.hpp"
#include "opspace/kinematics.hpp"
#include "opspace/urdf.hpp"

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
      {"unknown_joint_type.urdf", ":6: joint 'shoulder' has unknown type 'rotational'"},
      {"floating.urdf", ":6: joint 'free' is floating: not supported"},
      {"planar.urdf", ":6: joint 'slide' is planar: not supported"},
      {"mimic.urdf", ":14: joint 'finger2' mimics joint 'finger1': mimic joints are not supported"},
      {"loop.urdf", ":18: link 'c' is the child of both joint 'j2' and joint 'j3': a loop"},
      {"second_root.urdf", ":6: second root link: links 'base' and 'stray' are both without a parent joint"},
      {"cycle.urdf", ":6: link 'a' cannot be reached from the root 'base': its joints form a loop"},
      {"undeclared_link.urdf", ":5: joint 'j1' refers to link 'arm', which is not declared"},
      {"negative_mass.urdf", ":5: link 'arm' has mass -2 kg; a mass must be >= 0"},
      {"indefinite_inertia.urdf", ":6: link 'arm' has an inertia that is not positive definite"},
      {"missing_limit.urdf", ": urdfdom rejected the file: "},
  };
  for (const Case& c : table) {
    const std::string path = broken(c.file);
    CAPTURE(path);
    const std::string what = load_error(path);
    CHECK_MESSAGE(what.rfind(path + c.message, 0) == 0, "expected \"", path + c.message, "...\", got \"", what, "\"");
  }
}
