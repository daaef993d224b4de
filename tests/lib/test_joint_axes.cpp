// forward_kinematics composes rotations about coordinate axes by a plane rotation of two columns
// and about any other axis by Rodrigues' formula (lib/src/math/spatial.hpp): both must give
// the definition, oMi = oMparent * placement * joint(q_i), on every robot and on a test tree with
// tilted, signed and prismatic axes (tests/data/tilted_axes.urdf, which test_dynamics.cpp also
// checks against the identities of rigid-body dynamics).
#include <doctest/doctest.h>

#include <string>

#include "opspace/algorithms/kinematics.hpp"
#include "opspace/math/constants.hpp"
#include "opspace/model/urdf.hpp"
#include "grader/suite/random.hpp"

using namespace opspace;

namespace {

/// The pose of every body by the definition: Isometry3d products, the joint's motion as an
/// AngleAxis rotation or a translation along the axis.
std::vector<Eigen::Isometry3d> poses_by_definition(const Model& model, const Eigen::VectorXd& q) {
  std::vector<Eigen::Isometry3d> pose(model.bodies.size());
  for (int i = 0; i < model.dof(); ++i) {
    const Body& body = model.bodies[i];
    Eigen::Isometry3d joint = Eigen::Isometry3d::Identity();
    if (body.type == JointType::kRevolute) {
      joint.linear() = Eigen::AngleAxisd(q(i), body.axis).toRotationMatrix();
    } else {
      joint.translation() = q(i) * body.axis;
    }
    const Eigen::Isometry3d parent = body.parent < 0 ? Eigen::Isometry3d::Identity() : pose[body.parent];
    pose[i] = parent * body.joint_placement * joint;
  }
  return pose;
}

}  // namespace

TEST_CASE("forward kinematics about any joint axis is the composition of placements and joint motions") {
  const std::string files[] = {robot_path("pp.urdf"), robot_path("puma.urdf"), robot_path("iiwa7.urdf"),
                               robot_path("rrr.urdf"), std::string(OPSPACE_TEST_DATA_DIR) + "/tilted_axes.urdf"};
  testing::Random rng(31);
  for (const std::string& file : files) {
    CAPTURE(file);
    const Model model = load_urdf(file);
    Data data(model);
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::VectorXd q(model.dof());
      for (int i = 0; i < model.dof(); ++i) q(i) = model.bodies[i].type == JointType::kRevolute ? rng.uniform(-kPi, kPi) : rng.uniform(-1, 1);
      forward_kinematics(model, data, q);
      const std::vector<Eigen::Isometry3d> expected = poses_by_definition(model, q);
      for (int i = 0; i < model.dof(); ++i) {
        CAPTURE(i);
        // Both are a few products of unit-size rotations and sub-metre translations, in another
        // order: they differ by rounding, a few 1e-16 per product.
        CHECK((data.body_pose[i].matrix() - expected[i].matrix()).cwiseAbs().maxCoeff() < 1e-14);
      }
    }
  }
}
