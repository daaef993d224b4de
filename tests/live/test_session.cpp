// A live session without clock or browser (lib/src/live/session.cpp, problems/1b/run/lab.cpp): the same
// steps as the offline run, the page's commands, a scripted push under PART2 and PART3, and a
// controller that fails.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>
#include <fstream>
#include <string>
#include <vector>

#include <problems/1b/contract.hpp>
#include <problems/2/contract.hpp>
#include <problems/3/contract.hpp>
#include <problems/4/contract.hpp>
#include "opspace/algorithms/dynamics.hpp"
#include "opspace/algorithms/kinematics.hpp"
#include <problems/1b/run/lab.hpp>
#include <problems/2/run/lab.hpp>
#include <problems/3/run/lab.hpp>
#include <problems/4/run/lab.hpp>
#include "opspace/live/run.hpp"
#include "opspace/live/session.hpp"

using namespace opspace;
using hw2::p1b::Part;
namespace p1b = scenarios::p1b;

namespace {

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("opspace-test-live-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

}  // namespace

// Runs `offline` (an offline run writing its log at the path it is given) and `lab` unpaced for
// `duration` s, and checks that the live log is the offline log with the session's columns
// after it, row for row, digit for digit.
template <class Offline>
void check_same_log(live::Lab& lab, Offline offline, double duration, const std::string& name) {
  const std::string offline_csv = scratch(name + "-offline.csv"), live_csv = scratch(name + "-live.csv");
  scenarios::RunOptions options;
  options.duration = duration;
  options.csv_path = offline_csv;
  const std::size_t samples = offline(options);
  {
    live::Session session(lab, live_csv);
    live::run_unpaced(session, duration);
    CHECK(session.error().empty());
  }
  const std::vector<std::string> a = lines_of(offline_csv), b = lines_of(live_csv);
  REQUIRE(a.size() == samples + 1);  // the header and one row per millisecond
  REQUIRE(b.size() == a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    REQUIRE_MESSAGE(b[i].compare(0, a[i].size() + 1, a[i] + ",") == 0,
                    name << ", line " << i + 1 << "\noffline: " << a[i] << "\nlive:    " << b[i]);
  }
  CHECK(b[0].substr(a[0].size()) == ",law,speed,push_body,push_fx,push_fy,push_fz,resets,kpx,kvx,kvj");
}

TEST_CASE("the live loop, unpaced and with no input, logs what the offline run logs") {
  // The graded path is the offline run: the live lab must step the same closed loop, for every
  // problem. 0.5 s: 500 ticks of each law, contact included for problem 3 (it touches at once).
  live::P1bLab p1b_lab("hw2-p1", Part::kDynamicallyConsistentNullspace, &hw2::p1b::control);
  check_same_log(p1b_lab, [](const scenarios::RunOptions& o) {
    return p1b::run(Part::kDynamicallyConsistentNullspace, &hw2::p1b::control, o).samples.size();
  }, 0.5, "p1b");
  live::P2Lab p2_lab("hw2-p2", &hw2::p2::control, &hw2::p2::desired_acceleration);
  check_same_log(p2_lab, [](const scenarios::RunOptions& o) {
    return scenarios::p2::run(&hw2::p2::control, &hw2::p2::desired_acceleration, o).samples.size();
  }, 0.5, "p2");
  live::P3Lab p3_lab("hw2-p3", &hw2::p3::control);
  check_same_log(p3_lab, [](const scenarios::RunOptions& o) {
    return scenarios::p3::run(&hw2::p3::control, o).samples.size();
  }, 0.5, "p3");
  live::P4Lab p4_lab("hw2-p4", hw2::p4::Target::kAlongZ0, &hw2::p4::control);
  check_same_log(p4_lab, [](const scenarios::RunOptions& o) {
    return scenarios::p4::run(hw2::p4::Target::kAlongZ0, &hw2::p4::control, o).samples.size();
  }, 0.5, "p4");
}

TEST_CASE("pause holds the time, reset returns to the start, the law and gains switch live") {
  live::P1bLab lab("hw2-p1", Part::kDynamicallyConsistentNullspace, &hw2::p1b::control);
  live::Session session(lab, "");
  for (int k = 0; k < 100; ++k) session.step();
  CHECK(session.time() == doctest::Approx(0.1));
  session.submit(R"({"id":1,"command":"pause"})");
  session.apply_queued();
  session.step();
  CHECK_MESSAGE(session.time() == doctest::Approx(0.1), "paused: no step");
  session.submit(R"({"id":2,"command":"resume"})");
  session.submit(R"({"id":3,"command":"law","value":1})");
  session.submit(R"({"id":4,"command":"gain","name":"kvj","value":5})");
  session.apply_queued();
  session.step();
  CHECK(lab.part() == Part::kPseudoInverseNullspace);
  CHECK(session.time() == doctest::Approx(0.101));
  const std::string frame = session.frame(1.0);
  CHECK_MESSAGE(frame.find("\"law\":1") != std::string::npos, frame);
  CHECK_MESSAGE(frame.find("\"kvj\":5") != std::string::npos, frame);
  CHECK_MESSAGE(frame.find("\"command\":4") != std::string::npos, "the frame names the last command applied");
  session.submit(R"({"id":5,"command":"reset"})");
  session.apply_queued();
  CHECK(session.time() == 0.0);
  CHECK_MESSAGE(lab.part() == Part::kDynamicallyConsistentNullspace, "a reset restores the starting law");
  CHECK((lab.simulation().q() - p1b::initial_q()).norm() == 0.0);
  CHECK_THROWS_AS(session.submit(R"({"id":6,"command":"law","value":7})"), live::CommandError);
}

TEST_CASE("a push from the page pulls the picked link with the spring until it is released") {
  live::P1bLab lab("hw2-p1", Part::kDynamicallyConsistentNullspace, &hw2::p1b::control);
  live::Session session(lab, "");
  // The elbow (body 2, the PUMA's third of six bodies) pulled 10 cm up from where it is.
  const Eigen::Vector3d elbow = lab.simulation().body_pose(2).translation();
  session.submit(R"({"id":1,"command":"push","body":2,"point":[0,0,0],"target":[)" + std::to_string(elbow.x()) + "," +
                 std::to_string(elbow.y()) + "," + std::to_string(elbow.z() + 0.1) + "]}");
  session.apply_queued();
  session.step();
  const std::string pushing = session.frame(1.0);
  CHECK_MESSAGE(pushing.find("\"push\":{\"body\":2") != std::string::npos, pushing);
  CHECK_MESSAGE(pushing.find("\"force\":[") != std::string::npos, "the frame carries the spring's force");
  session.submit(R"({"id":2,"command":"release"})");
  session.apply_queued();
  CHECK(session.frame(1.0).find("\"push\":null") != std::string::npos);
  CHECK_THROWS_AS(session.submit(R"({"id":3,"command":"push","body":6,"point":[0,0,0],"target":[0,0,0]})"),
                  live::CommandError);
}

TEST_CASE("a controller that returns NaN stops the run with its message, and a reset starts again") {
  bool fail = true;
  live::P1bLab lab("hw2-p1", Part::kDynamicallyConsistentNullspace,
                   [&](Part part, const hw2::p1b::State& s, const hw2::p1b::Goal& g) {
                     p1b::Vector6d tau = hw2::p1b::control(part, s, g);
                     if (fail && s.t >= 0.05) tau(2) = NAN;
                     return tau;
                   });
  live::Session session(lab, "");
  for (int k = 0; k < 200; ++k) session.step();
  CHECK_MESSAGE(session.error().find("returned NaN in tau[2]") != std::string::npos, session.error());
  CHECK(session.time() == doctest::Approx(0.05));
  CHECK_MESSAGE(session.frame(0.0).find("returned NaN") != std::string::npos, "the page sees the message");
  fail = false;
  session.submit(R"({"id":1,"command":"reset"})");
  session.apply_queued();
  for (int k = 0; k < 100; ++k) session.step();
  CHECK(session.error().empty());
  CHECK(session.time() == doctest::Approx(0.1));
}

namespace {

struct PushResponse {
  double deviation = 0.0;  // max |x_pushed(t) - x_unpushed(t)| over 3..5 s (m)
  double steady = 0.0;     // |Jv A^-1 Je^T F| / kpx at the push's start (m)
};

// A push of `force` on the elbow (link lower_arm, at the elbow joint) from t = 3 s to 3.2 s
// under `part`, against the same run unpushed.
PushResponse push_response(Part part, const Eigen::Vector3d& force) {
  live::P1bLab pushed("hw2-p1", part, &hw2::p1b::control), still("hw2-p1", part, &hw2::p1b::control);
  const Model& puma = pushed.simulation().model();
  const int elbow = puma.joint_id("elbow");
  const int tip = puma.frame_id(p1b::kTipLink), elbow_frame = puma.frame_id(puma.bodies[elbow].link_name);
  Data data(puma);
  PushResponse r;
  for (long k = 0; k <= 5000; ++k) {
    const double t = k * 1e-3;
    const Eigen::VectorXd tau_pushed = pushed.tick(), tau_still = still.tick();
    if (t >= 3.0) r.deviation = std::max(r.deviation, (pushed.result().samples.back().x - still.result().samples.back().x).norm());
    if (k == 3000) {  // the tip acceleration the push causes, Jv A^-1 Je^T F, over kpx
      const Eigen::MatrixXd A = crba(puma, data, pushed.simulation().q());
      Matrix6Xd Jt(6, 6), Je(6, 6);
      point_jacobian(puma, data, tip, p1b::tip_point(), Jt);
      point_jacobian(puma, data, elbow_frame, Eigen::Vector3d::Zero(), Je);
      const Eigen::Vector3d xdd = Jt.topRows<3>() * A.llt().solve(Je.topRows<3>().transpose() * force);
      r.steady = xdd.norm() / p1b::goal(t, p1b::initial_q()).kpx;
    }
    if (t >= 3.0 && t < 3.2) {
      forward_kinematics(puma, data, pushed.simulation().q());
      pushed.simulation().push(elbow, force, data.body_pose[elbow].translation());
    }
    pushed.simulation().step(tau_pushed);
    still.simulation().step(tau_still);
  }
  return r;
}

}  // namespace

TEST_CASE("a push on the elbow moves the tip far less under PART3 than under PART2") {
  // 30 N upward on the elbow for 0.2 s, 3 s into the run (past kSettleTime): a firm push.
  const Eigen::Vector3d force(0.0, 0.0, 30.0);
  const PushResponse part3 = push_response(Part::kDynamicallyConsistentNullspace, force);
  const PushResponse part2 = push_response(Part::kPseudoInverseNullspace, force);
  MESSAGE("tip deviation from the push: PART2 " << part2.deviation * 1e3 << " mm, PART3 " << part3.deviation * 1e3
          << " mm; PART3's steady offset |Jv A^-1 Je^T F| / kpx = " << part3.steady * 1e3 << " mm");
  // PART3: the push reaches the tip only as the task-space force Jbar^T Je^T F, which the tip's
  // PD resists in the decoupled task dynamics e'' + kvx e' + kpx e = Jv A^-1 Je^T F: an
  // overdamped response (kvx = 20 > 2 sqrt(kpx) = 14.1) to a pulse never exceeds the step's
  // steady offset |Jv A^-1 Je^T F| / kpx; 1.5 x leaves room for the pose's change under the push.
  CHECK(part3.deviation <= 1.5 * part3.steady);
  // PART2: the joint task's torque, which fights the elbow's displacement, reaches the tip
  // through (I - Jv+ Jv)^T, which does not filter it out of the task (it is not Jbar's), and
  // the drift it starts grows: ten times PART3's at the least.
  CHECK(part2.deviation >= 10.0 * part3.deviation);
}
