// A whole control tick allocates nothing on the heap: the library computes the controller's
// State (kinematics, A, g, Lambda, Jbar, p) and the reference law turns it into torques,
// with fixed-size matrices and workspaces sized once. (Linked with solutions/.)
#include <doctest/doctest.h>

#include "opspace/scenarios.hpp"
#include "opspace/urdf.hpp"
#include "support/count_allocations.hpp"

using opspace::hw2::p1b::Part;

TEST_CASE("a problem-1b control tick allocates nothing once its workspaces exist") {
  namespace p1b = opspace::scenarios::p1b;
  const opspace::Model puma = opspace::load_urdf(opspace::robot_path(p1b::kRobotFile));
  p1b::Observer observer(puma);
  const p1b::Vector6d q = p1b::initial_q();
  const p1b::Vector6d dq = p1b::Vector6d::LinSpaced(0.3, -0.2);
  p1b::Vector6d sink = p1b::Vector6d::Zero();
  observer.observe(0.0, q, dq);  // warm-up: nothing is lazily sized, but measure a steady tick
  for (const Part part : {Part::kTipPd, Part::kTipPdWithoutJointDamping, Part::kPseudoInverseNullspace,
                          Part::kDynamicallyConsistentNullspace}) {
    CAPTURE(static_cast<int>(part));
    const long n = allocations_in([&] {
      const opspace::hw2::p1b::State& s = observer.observe(0.5, q, dq);
      sink += opspace::hw2::p1b::control(part, s, p1b::goal(0.5, s.q));
    });
    CHECK_MESSAGE(n == 0, "one tick allocated ", n, " times");
  }
  CHECK(sink.allFinite());
}
