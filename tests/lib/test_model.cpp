// Model and Data: the workspace is sized once from the model, and lookups and size checks
// fail with messages that name what was asked for and the model.
#include <doctest/doctest.h>

#include "opspace/model/model.hpp"
#include "opspace/model/urdf.hpp"

using namespace opspace;

TEST_CASE("a Data is sized from its model once, for every algorithm") {
  const Model model = load_urdf(robot_path("iiwa7.urdf"));  // 7 joints
  const Data data(model);
  CHECK(data.body_pose.size() == 7);
  CHECK(data.A.rows() == 7);
  CHECK(data.A.cols() == 7);
  CHECK(data.g.size() == 7);
  CHECK(data.b.size() == 7);
  CHECK(data.tau.size() == 7);
  CHECK(data.qdd.size() == 7);
  CHECK(data.v.size() == 7);
  CHECK(data.a.size() == 7);
  CHECK(data.f.size() == 7);
  CHECK(data.S.size() == 7);
  CHECK(data.Ic.size() == 7);
}

TEST_CASE("frames and joints are found by name") {
  // iiwa7.urdf: link0 is the fixed base (body -1), link7 is moved by the 7th joint j7.
  const Model model = load_urdf(robot_path("iiwa7.urdf"));
  CHECK(model.frames[model.frame_id("link0")].body == -1);
  CHECK(model.frames[model.frame_id("link7")].body == model.joint_id("j7"));
  CHECK(model.joint_id("j7") == 6);
}

TEST_CASE("a joint vector of the wrong size is named with both sizes") {
  const Model model = load_urdf(robot_path("pp.urdf"));
  CHECK_NOTHROW(model.check_joint_vector(Eigen::VectorXd::Zero(2), "q"));
  CHECK_THROWS_WITH_AS(model.check_joint_vector(Eigen::VectorXd::Zero(3), "qdot"),
                       doctest::Contains("qdot has 3 entries, but model 'pp'"), std::invalid_argument);
}
