// A control tick must not touch the heap: once a Data exists, the kinematics and dynamics
// calls allocate nothing (every heap allocation of the process is counted).
#include <doctest/doctest.h>

#include <string>

#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include "opspace/model/urdf.hpp"
#include "support/count_allocations.hpp"

using namespace opspace;

TEST_CASE("the allocation counter sees Eigen's heap allocations") {
  // Positive control: a dynamic-size vector must be counted, or the next test proves nothing.
  long size = 0;
  const long n = allocations_in([&] {
    Eigen::VectorXd v = Eigen::VectorXd::Ones(100);
    size = v.size();
  });
  CHECK(size == 100);
  CHECK_MESSAGE(n >= 1, "the counter missed a VectorXd allocation");
}

TEST_CASE("kinematics and dynamics allocate nothing once Data exists") {
  for (const char* file : {"puma.urdf", "iiwa7.urdf", "pp.urdf", "rrr.urdf"}) {
    CAPTURE(file);
    const Model model = load_urdf(robot_path(file));
    Data data(model);
    const Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(model.dof(), -0.7, 0.9);
    const Eigen::VectorXd qdot = Eigen::VectorXd::LinSpaced(model.dof(), 0.5, -0.4);
    const Eigen::VectorXd tau = Eigen::VectorXd::LinSpaced(model.dof(), 1.0, -1.0);
    Matrix6Xd J0(6, model.dof());
    const int tip = static_cast<int>(model.frames.size()) - 1;
    const Eigen::Vector3d p(0.1, 0.0, 0.05);
    Vector6d sink = Vector6d::Zero();

    const long n = allocations_in([&] {
      forward_kinematics(model, data, q);
      sink += Vector6d::Constant(point_position(model, data, tip, p).sum());
      point_jacobian(model, data, tip, p, J0);
      sink += point_velocity(model, data, tip, p, qdot);
      sink += point_jacobian_dot_times_qdot(model, data, tip, p, q, qdot);
      crba(model, data, q);
      generalized_gravity(model, data, q);
      mass_matrix_and_gravity(model, data, q);
      coriolis_centrifugal(model, data, q, qdot);
      rnea(model, data, q, qdot, tau);
      forward_dynamics(model, data, q, qdot, tau);
    });
    CHECK(sink.allFinite());
    CHECK_MESSAGE(n == 0, "a control-loop call allocated ", n, " times: size the workspace in Data instead");
  }
}
