// A Model as text (model_text.hpp), as the explorer's WebAssembly module receives it: read back,
// it is the Model that was written, number for number; broken text is refused with its line.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <stdexcept>
#include <string>

#include "opspace/dynamics.hpp"
#include "opspace/model_text.hpp"
#include "opspace/urdf.hpp"

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
