// A Model as text (model_text.hpp), as the explorer's WebAssembly module receives it: read back,
// it is the Model that was written, number for number; broken text is refused with its line.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/model/model_text.hpp"
#include "opspace/model/urdf.hpp"

using opspace::Model;
using opspace::read_model_text;
using opspace::write_model_text;

namespace {

bool same_shapes(const std::vector<opspace::Shape>& a, const std::vector<opspace::Shape>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].kind != b[i].kind || a[i].box_size != b[i].box_size || a[i].radius != b[i].radius ||
        a[i].length != b[i].length || a[i].body != b[i].body || a[i].link != b[i].link ||
        !a[i].placement.isApprox(b[i].placement, 0.0)) {
      return false;
    }
  }
  return true;
}

/// Every field, compared exactly (==): 17 significant digits round-trip a double.
void check_same(const Model& a, const Model& b) {
  CHECK(a.name == b.name);
  CHECK(a.gravity == b.gravity);
  CHECK(a.base_inertia.mass == b.base_inertia.mass);
  REQUIRE(a.dof() == b.dof());
  for (int i = 0; i < a.dof(); ++i) {
    const opspace::Body &x = a.bodies[i], &y = b.bodies[i];
    INFO("joint ", x.joint_name);
    CHECK(x.joint_name == y.joint_name);
    CHECK(x.link_name == y.link_name);
    CHECK(x.type == y.type);
    CHECK(x.parent == y.parent);
    CHECK(x.joint_placement.matrix() == y.joint_placement.matrix());
    CHECK(x.axis == y.axis);
    CHECK(x.inertia.mass == y.inertia.mass);
    CHECK(x.inertia.com == y.inertia.com);
    CHECK(x.inertia.inertia == y.inertia.inertia);
    CHECK((x.lower == y.lower && x.upper == y.upper && x.effort == y.effort && x.velocity == y.velocity));
  }
  REQUIRE(a.frames.size() == b.frames.size());
  for (std::size_t i = 0; i < a.frames.size(); ++i) {
    CHECK(a.frames[i].name == b.frames[i].name);
    CHECK(a.frames[i].body == b.frames[i].body);
    CHECK(a.frames[i].placement.matrix() == b.frames[i].placement.matrix());
  }
  CHECK(same_shapes(a.visuals, b.visuals));
  CHECK(same_shapes(a.collisions, b.collisions));
}

std::string robot_text(const char* file) { return write_model_text(opspace::load_urdf(opspace::robot_path(file))); }

/// Where line `line` (1-based) of `text` begins.
std::size_t line_start(const std::string& text, int line) {
  std::size_t begin = 0;
  for (int k = 1; k < line; ++k) begin = text.find('\n', begin) + 1;
  return begin;
}

/// `text` with line `line` (1-based) replaced.
std::string with_line(const std::string& text, int line, const std::string& replacement) {
  const std::size_t begin = line_start(text, line);
  const std::size_t end = text.find('\n', begin);
  return text.substr(0, begin) + replacement + text.substr(end);
}

}  // namespace

TEST_CASE("each robot read back from its text is the Model it was written from, number for number") {
  for (const char* file : {"pp.urdf", "puma.urdf", "iiwa7.urdf", "rrr.urdf"}) {
    INFO(file);
    const Model urdf = opspace::load_urdf(opspace::robot_path(file));
    const Model text = read_model_text(write_model_text(urdf), file);
    check_same(urdf, text);
    CHECK(write_model_text(text) == write_model_text(urdf));
    // Same numbers, same arithmetic: the same mass matrix bit for bit.
    const Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(urdf.dof(), 0.1, 0.7);
    opspace::Data da(urdf), db(text);
    CHECK(opspace::crba(urdf, da, q) == opspace::crba(text, db, q));
  }
}

TEST_CASE("names with blanks, percent signs or nothing at all survive the text") {
  Model m = opspace::load_urdf(opspace::robot_path("pp.urdf"));
  m.name = "my robot 100%";
  m.bodies[0].joint_name = "";
  m.bodies[1].link_name = "tab\there";
  const Model back = read_model_text(write_model_text(m), "edited");
  CHECK(back.name == m.name);
  CHECK(back.bodies[0].joint_name.empty());
  CHECK(back.bodies[1].link_name == m.bodies[1].link_name);
}

TEST_CASE("a broken model text is refused with its line and what is wrong") {
  using doctest::Contains;
  const std::string pp = robot_text("pp.urdf");
  // pp.urdf's text: 1 header, 2 robot, 3 gravity, 4 base, 5-6 bodies d1 and d2.
  CHECK_THROWS_WITH_AS(read_model_text("", "t"), Contains("t:0: the text ends before 'end'"), std::invalid_argument);
  // Cut short at a line's end (a cut inside a line is refused by that line's missing field).
  CHECK_THROWS_WITH_AS(read_model_text(pp.substr(0, pp.rfind("end\n")), "t"), Contains("ends before 'end'"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(read_model_text(pp.substr(0, pp.find('\n', line_start(pp, 6)) - 20), "t"),
                       Contains("t:6: missing"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(read_model_text(with_line(pp, 1, "<robot name=\"x\">"), "t"),
                       Contains("t:1: not an opspace model text"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(read_model_text(with_line(pp, 3, "gravity 0 0 nan"), "t"),
                       Contains("t:3: gravity is 'nan', not a finite number"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(read_model_text(with_line(pp, 3, "gravity 0 0"), "t"), Contains("t:3: missing gravity"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(read_model_text(with_line(pp, 3, "gravity 0 0 -9.81 7"), "t"),
                       Contains("t:3: unexpected '7'"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(read_model_text(with_line(pp, 2, "joint d1"), "t"), Contains("t:2: unknown record 'joint'"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(read_model_text(pp + "robot again\n", "t"), Contains("text after 'end'"), std::invalid_argument);
  // Body d1 with its parent set to itself (index 0): parents must come first.
  const std::size_t line5 = line_start(pp, 5);
  std::string d1 = pp.substr(line5, pp.find('\n', line5) - line5);
  std::string self_parent = d1;
  self_parent.replace(self_parent.find(" -1 "), 4, " 0 ");
  CHECK_THROWS_WITH_AS(read_model_text(with_line(pp, 5, self_parent), "t"),
                       Contains("t:5: parent 0 is not an index in [-1, 0)"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(read_model_text(with_line(pp, 4, "base -1 0 0 0 0 0 0 0 0 0 0 0 0"), "t"),
                       Contains("t:4: base inertia: negative mass"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(read_model_text(with_line(pp, 2, "robot a%zz"), "t"), Contains("t:2: bad escape"),
                       std::invalid_argument);
  Model zero_axis = opspace::load_urdf(opspace::robot_path("pp.urdf"));
  zero_axis.bodies[1].axis.setZero();
  CHECK_THROWS_WITH_AS(read_model_text(write_model_text(zero_axis), "t"), Contains("t:6: joint 'd2' has a zero axis"),
                       std::invalid_argument);
}

namespace {

/// The 1-based line of `text` on which the first record `record` stands.
int line_of(const std::string& text, const std::string& record) {
  const std::size_t at = text.find("\n" + record + " ");
  REQUIRE(at != std::string::npos);
  return 2 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

/// What read_model_text says of the text of `m`.
std::string refusal(const Model& m) {
  try {
    read_model_text(write_model_text(m), "t");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_CASE("a joint without limits, as a continuous joint loads, survives the text") {
  // The URDF loader gives a continuous joint (or one without <limit>) the limits -inf and inf.
  Model m = opspace::load_urdf(opspace::robot_path("rrr.urdf"));
  m.bodies[0].lower = -std::numeric_limits<double>::infinity();
  m.bodies[0].upper = std::numeric_limits<double>::infinity();
  check_same(m, read_model_text(write_model_text(m), "continuous"));
}

TEST_CASE("a model text that the URDF loader could not have made is refused with its line") {
  // Each edit breaks one rule that load_urdf enforces (lib/src/model/urdf_build.cpp) on the PP
  // robot's d2 (line 6), its first visual shape, or its base (line 4).
  const Model pp = opspace::load_urdf(opspace::robot_path("pp.urdf"));
  const int visual_line = line_of(write_model_text(pp), "visual");
  using doctest::Contains;
  Model m = pp;
  m.bodies[1].joint_placement.linear() *= 2.0;  // a scaling, not a rotation
  CHECK_MESSAGE(refusal(m).find("t:6: joint placement: its 3x3 part is not a rotation") == 0, refusal(m));
  m = pp;
  m.bodies[1].joint_placement.linear() = Eigen::Vector3d(1, 1, -1).asDiagonal();  // a reflection
  CHECK_MESSAGE(refusal(m).find("t:6: joint placement: its 3x3 part is not a rotation") == 0, refusal(m));
  m = pp;
  m.bodies[1].axis *= 2.0;
  CHECK_MESSAGE(refusal(m) == "t:6: joint 'd2' has an axis that is not a unit vector", refusal(m));
  m = pp;
  std::swap(m.bodies[1].lower, m.bodies[1].upper);
  CHECK_MESSAGE(refusal(m) == "t:6: joint 'd2' has its lower limit above its upper limit", refusal(m));
  m = pp;
  m.bodies[1].effort = -1.0;
  CHECK_MESSAGE(refusal(m) == "t:6: joint 'd2' has a negative effort or velocity limit", refusal(m));
  m = pp;
  m.bodies[1].inertia.inertia(0, 1) = 1.0;  // I_xy without I_yx
  CHECK_MESSAGE(refusal(m) == "t:6: body inertia: inertia matrix not symmetric", refusal(m));
  m = pp;
  m.base_inertia.inertia = Eigen::Vector3d(1, 1, -1).asDiagonal();  // a negative principal moment
  // The eigenvalues of a diagonal matrix are its entries, ascending: -1 first.
  CHECK_MESSAGE(refusal(m).find("t:4: base inertia: inertia matrix not positive semi-definite (eigenvalues -1 ") == 0,
                refusal(m));
  m = pp;
  REQUIRE(!m.visuals.empty());
  m.visuals[0].radius = -0.1;
  // A control character from the text is written \xNN: the message may reach a terminal.
  CHECK_THROWS_WITH_AS(read_model_text("opspace-model 1\n\x1b[2J x\n", "t"), "t:2: unknown record '\\x1b[2J'",
                       std::invalid_argument);
  const std::string shape = "t:" + std::to_string(visual_line) + ": shape of link '" + m.visuals[0].link + "' has a negative size";
  CHECK_MESSAGE(refusal(m) == shape, refusal(m));
}
