// mass_matrix_and_gravity() is crba() and generalized_gravity() sharing one forward-kinematics
// pass: it must give what the two calls give, and leave the poses of its own q in Data.
#include <doctest/doctest.h>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/model/urdf.hpp"
#include "grader/suite/random.hpp"

using namespace opspace;

TEST_CASE("A and g from one kinematics pass equal those of crba and generalized_gravity") {
  for (const char* file : {"pp.urdf", "puma.urdf", "iiwa7.urdf", "rrr.urdf"}) {
    CAPTURE(file);
    const Model model = load_urdf(robot_path(file));
    Data combined(model), separate(model);
    testing::Random rng(41);
    const int tip = static_cast<int>(model.frames.size()) - 1;
    for (int trial = 0; trial < 5; ++trial) {
      const Eigen::VectorXd q = rng.vector(model.dof());
      // Leave the poses of another configuration in Data first: a function that skipped the
      // kinematics would then compute A and g at the wrong pose.
      forward_kinematics(model, combined, -q);
      mass_matrix_and_gravity(model, combined, q);
      // The same arithmetic in the same order: the results agree to the last bit.
      CHECK(combined.A == crba(model, separate, q));
      CHECK(combined.g == generalized_gravity(model, separate, q));
      CHECK(frame_pose(model, combined, tip).matrix() == frame_pose(model, separate, tip).matrix());
    }
  }
}
