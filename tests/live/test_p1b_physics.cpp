// Problem 1b live (problems/1b/run/lab.cpp, offset.cpp): what its page says of the physics,
// measured on the live lab's own loop (a Session stepped without clock or browser) with the
// reference controller. Derivation: problems/1b/run/offset.hpp and docs/live.md ("What a push does to
// the tip"): under PART3 the tip error e = x - x_d obeys
//   dde + kvx de + kpx e = Jv A^-1 Je^T F + (dJv dq - Jv A^-1 b),
// so a steady push F holds the tip, once the arm is still, at e = Jv A^-1 Je^T F / kpx, the
// prediction the page plots; with no push only the velocity terms are left.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <problems/1b/contract.hpp>
#include <problems/1b/run/lab.hpp>
#include "opspace/live/run.hpp"
#include "opspace/live/session.hpp"

using namespace opspace;
using hw2::p1b::Part;
namespace p1b = scenarios::p1b;

namespace {

constexpr double kDt = 1e-3;   // the simulation's step (s)
constexpr double kKpx = 50.0;  // problem 1b's tip gains (p1b::goal): stiffness (1/s^2)
constexpr double kKvx = 20.0;  // and damping (1/s)

// What a run recorded at each tick: tip error, the page's prediction, joint speed.
struct Trace {
  std::vector<Eigen::Vector3d> e, predicted;
  std::vector<double> speed;
};

// Steps `lab` for `seconds` through a Session, as the page would; from `push_from` on, the
// elbow (body 2's origin) is pulled by the page's spring toward a point 1.45 m off. The spring
// pulls with m (2 pi x 1 Hz)^2 |d| = 57 m N there: at its 50 N cap for any effective mass m above
// 0.9 kg (the elbow carries the forearm and wrist: more), and it stays there while the elbow
// moves by centimetres: a steady push.
Trace run(live::P1bLab& lab, double seconds, double push_from = -1.0) {
  live::Session session(lab, "");
  const Eigen::Vector3d x_d = p1b::goal(0.0, p1b::initial_q()).x_d;
  Trace trace;
  const long steps = std::lround(seconds / kDt), push_step = std::lround(push_from / kDt);
  for (long k = 0; k <= steps; ++k) {
    if (k == push_step) {
      const Eigen::Vector3d target = lab.simulation().body_pose(2).translation() + Eigen::Vector3d(0.3, -0.3, 1.3);
      session.submit(R"({"id":1,"command":"push","body":2,"point":[0,0,0],"target":[)" + std::to_string(target.x()) +
                     "," + std::to_string(target.y()) + "," + std::to_string(target.z()) + "]}");
      session.apply_queued();
    }
    session.step(k < steps);
    trace.e.push_back(lab.result().samples.back().x - x_d);
    trace.predicted.push_back(lab.predicted_offset());
    trace.speed.push_back(lab.simulation().qdot().norm());
  }
  return trace;
}

// PART3 with joint 2's goal held at its start: the same law and gains, but a null-space task
// that lets the arm come to rest under a steady push.
hw2::p1b::Vector6d part3_held(Part part, const hw2::p1b::State& s, const hw2::p1b::Goal& goal) {
  hw2::p1b::Goal held = goal;
  held.q_d(1) = p1b::initial_q()(1);
  return hw2::p1b::control(part, s, held);
}

// Max |e| over [from, to] s.
double largest_error(const Trace& trace, double from, double to) {
  double largest = 0.0;
  for (long k = std::lround(from / kDt); k <= std::lround(to / kDt); ++k) largest = std::max(largest, trace.e[k].norm());
  return largest;
}

}  // namespace

// Seen to fail: with the prediction written Lambda_v Jv A^-1 Je^T F / kpx in problems/1b/run/offset.cpp (a
// first guess), it said 116 mm where the tip stood 42 mm off, and the identity's residual was
// 3.7 m/s^2 (bound 0.83); with the prediction zero, 42 mm off and 3.5 m/s^2.
TEST_CASE("a steady push on the elbow holds PART3's tip at the page's prediction Jv A^-1 Je^T F / kpx") {
  // At rest. Pushed from 1 s for 9 s; the arm's null-space drift under the push decays (its joints
  // but joint 2 have damping alone), to about 0.01 rad/s by 10 s.
  live::P1bLab held("hw2-p1", Part::kDynamicallyConsistentNullspace, &part3_held);
  const Trace still = run(held, 10.0, 1.0);
  const long end = static_cast<long>(still.e.size()) - 1;
  const Eigen::Vector3d e = still.e[end], predicted = still.predicted[end];
  // What the identity leaves: the lag of the tip behind a prediction that still moves with the
  // drift, (kvx / kpx) |d predicted / dt| (the first term of the response of the task's
  // second-order dynamics to a slow input); the drift being nearly over, under 0.5 % of the offset.
  const double lag = kKvx / kKpx * (still.predicted[end] - still.predicted[end - 1]).norm() / kDt;
  MESSAGE("steady 50 N on the elbow, PART3, at 10 s: measured |e| = " << 1e3 * e.norm() << " mm, predicted "
          << 1e3 * predicted.norm() << " mm, |e - predicted| = " << 1e3 * (e - predicted).norm() << " mm, lag "
          << 1e3 * lag << " mm, joint speed " << still.speed[end] << " rad/s");
  CHECK(lag < 0.005 * predicted.norm());
  // The lag is the first term of what is left; the next ones (the prediction's second derivative
  // over kpx, the velocity terms, quadratic in the 0.01 rad/s left) are smaller still: 1 % of
  // the offset is twice the lag's bound just checked.
  CHECK((e - predicted).norm() <= 0.01 * predicted.norm());

  // Moving: the page's own scenario (joint 2 swinging), pushed from 1 s to 5 s. The identity
  // itself, with derivatives by central differences: dde + kvx de + kpx (e - predicted) is what
  // the law leaves out, dJv dq - Jv A^-1 b, of order |dq|^2 times the arm's reach (0.9 m from
  // joint 2 to the tip), where the push alone gives kpx |predicted|, about 2.5 m/s^2.
  live::P1bLab moving("hw2-p1", Part::kDynamicallyConsistentNullspace, &hw2::p1b::control);
  const Trace swing = run(moving, 5.0, 1.0);
  double residual = 0.0, largest_speed = 0.0;
  for (long k = std::lround(1.002 / kDt); k + 1 < static_cast<long>(swing.e.size()); ++k) {
    const Eigen::Vector3d dde = (swing.e[k + 1] - 2.0 * swing.e[k] + swing.e[k - 1]) / (kDt * kDt);
    const Eigen::Vector3d de = (swing.e[k + 1] - swing.e[k - 1]) / (2.0 * kDt);
    residual = std::max(residual, (dde + kKvx * de + kKpx * (swing.e[k] - swing.predicted[k])).norm());
    largest_speed = std::max(largest_speed, swing.speed[k]);
  }
  MESSAGE("joint 2 swinging: largest |dde + kvx de + kpx (e - predicted)| = " << residual << " m/s^2 at |dq| <= "
          << largest_speed << " rad/s");
  CHECK(residual <= largest_speed * largest_speed * 0.9);
}

// Seen to fail: with PART3's run given PART2's law (the pseudo-inverse projector), its tip went
// 702 mm off.
TEST_CASE("unpushed, PART3's tip stays within a millimetre while joint 2 swings, and PART2's wanders") {
  // One period of q2_d (10 s), errors after the start's transient (kSettleTime, 2 s: the tip
  // starts 2.3 mm off and its slow pole, -10 + sqrt(50) = -2.9 /s, leaves 0.01 mm of it).
  // PART3: the identity without a push leaves the velocity terms alone; joint 2 swings at up to
  // (pi/8)(2 pi/10) = 0.25 rad/s, so they are of order 0.25^2 x 0.9 m = 0.06 m/s^2, which the tip's
  // stiffness holds to 0.06 / kpx = 1.1 mm: "within a millimetre".
  live::P1bLab part3("hw2-p1", Part::kDynamicallyConsistentNullspace, &hw2::p1b::control);
  const double held = largest_error(run(part3, 10.0), p1b::kSettleTime, 10.0);
  // PART2: the joint task's torques (gravity among them) reach the tip through
  // Jv A^-1 (I - Jv^T Jv+^T), which is not zero: ten times PART3's bound at least, "centimetres".
  live::P1bLab part2("hw2-p1", Part::kPseudoInverseNullspace, &hw2::p1b::control);
  const double wandered = largest_error(run(part2, 10.0), p1b::kSettleTime, 10.0);
  MESSAGE("largest tip error after 2 s, no push: PART3 " << 1e3 * held << " mm, PART2 " << 1e3 * wandered << " mm");
  CHECK(held <= 1e-3);
  CHECK(wandered >= 10e-3);
}

// Seen to fail: with page() leaving the ghost out (run.cpp), "ghost":null after set_reference too.
TEST_CASE("the page carries the reference's tip path of each law, in the law switch's order") {
  live::P1bLab lab("hw2-p1", Part::kDynamicallyConsistentNullspace, &hw2::p1b::control);
  CHECK_MESSAGE(live::page(lab, 50.0).find(R"("ghost":null)") != std::string::npos, "no reference given: no ghost");
  // Two points (p, 0, 0), (p, 1, 0) for PART p: the page's law i must get PART i+1's path.
  lab.set_reference(0.02, [](Part part) {
    const double p = static_cast<int>(part);
    return std::vector<Eigen::Vector3d>{{p, 0.0, 0.0}, {p, 1.0, 0.0}};
  });
  const std::string page = live::page(lab, 50.0);
  CHECK_MESSAGE(page.find(R"("laws":["PART1: )") != std::string::npos, "law 0 is PART1, 1 PART2, 2 PART3");
  CHECK_MESSAGE(page.find(R"("step":0.02,"paths":[[1.0,0.0,0.0,1.0,1.0,0.0],[2.0,0.0,0.0,2.0,1.0,0.0],)"
                          R"([3.0,0.0,0.0,3.0,1.0,0.0]]})") != std::string::npos,
                page.substr(page.find("\"ghost\""), 200));
}
