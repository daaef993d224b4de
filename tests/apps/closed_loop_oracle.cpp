// closed-loop-oracle PROBLEM RUN SECONDS CSV: the CSV log of one -sol program's run, written by a
// second path that shares no code with the programs' closed loop (scenarios/loop.hpp), their
// rows (each scenario's csv_row) or their CSV writer (CsvLog): its own loop over the library's
// Simulation, each problem's Observer, goal and start, and solutions/' functions, its own rows
// and its own file. check_csv_identity.sh compares it with the program's log byte for byte.
//   PROBLEM RUN: 1b 1 | 1b 1-no-damping | 1b 2 | 1b 3 | 2 - | 3 - | 4 z | 4 z-plain | 4 y | 4 y-plain
// Written once, from the problem set, and checked against the programs before the generic loop
// replaced the four problems' loops: the same file from both paths was the proof.
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "opspace/algorithms/euler_params.hpp"
#include <problems/1b/contract.hpp>
#include <problems/2/contract.hpp>
#include <problems/3/contract.hpp>
#include <problems/4/contract.hpp>
#include "opspace/model/urdf.hpp"
#include <problems/1b/run/scenario.hpp>
#include <problems/2/run/scenario.hpp>
#include <problems/3/run/scenario.hpp>
#include <problems/4/run/scenario.hpp>
#include "opspace/simulation/simulation.hpp"

namespace {

using namespace opspace;

/// A CSV file: the header, then rows at 10 significant digits (as the programs' logs).
class Csv {
 public:
  Csv(const std::string& path, const std::vector<std::string>& columns) : file_(path) {
    if (!file_) throw std::runtime_error("cannot write " + path);
    for (std::size_t i = 0; i < columns.size(); ++i) file_ << (i ? "," : "") << columns[i];
    file_ << "\n" << std::setprecision(10);
  }
  Csv& operator<<(double v) {
    file_ << (first_ ? "" : ",") << v;
    first_ = false;
    return *this;
  }
  template <class Vector>
  Csv& all(const Vector& v) {
    for (Eigen::Index i = 0; i < v.size(); ++i) *this << v(i);
    return *this;
  }
  void end() {
    file_ << "\n";
    first_ = true;
  }

 private:
  std::ofstream file_;
  bool first_ = true;
};

/// Steps sim for `seconds` from its state: at each of the round(seconds / dt) + 1 instants,
/// tick(t) writes the row of t and returns the torques, applied for one step but after the last.
template <class Tick>
void simulate(Simulation& sim, double seconds, Tick tick) {
  const long steps = std::lround(seconds / sim.settings().dt);
  for (long k = 0; k <= steps; ++k) {
    const auto tau = tick(sim.time());
    if (k < steps) sim.step(tau);
  }
}

void run_p1b(const std::string& part_name, double seconds, const std::string& path) {
  namespace p1b = scenarios::p1b;
  using hw2::p1b::Part;
  const Part part = part_name == "1" ? Part::kTipPd
                    : part_name == "1-no-damping" ? Part::kTipPdWithoutJointDamping
                    : part_name == "2" ? Part::kPseudoInverseNullspace
                                       : Part::kDynamicallyConsistentNullspace;
  const Model puma = load_urdf(robot_path("puma.urdf"));
  p1b::Observer observer(puma);
  SimulationSettings settings;
  settings.max_joint_speed = 1000.0;  // problem 1b's bound (PART2's wrist spins)
  Simulation sim(puma, settings);
  sim.set_state(p1b::initial_q(), p1b::Vector6d::Zero());
  const Eigen::Vector3d x_d = p1b::goal(0.0, p1b::initial_q()).x_d;
  Csv csv(path, {"t", "x", "y", "z", "x_d", "y_d", "z_d", "tip_error", "q1", "q2", "q3", "q4", "q5", "q6", "q2_d",
                 "tau1", "tau2", "tau3", "tau4", "tau5", "tau6"});
  simulate(sim, seconds, [&](double t) {
    const hw2::p1b::State& s = observer.observe(t, sim.q(), sim.qdot());
    const hw2::p1b::Goal g = p1b::goal(t, s.q);
    const p1b::Vector6d tau = hw2::p1b::control(part, s, g);
    csv << t;
    csv.all(s.x).all(x_d) << (s.x - x_d).norm();
    csv.all(s.q) << g.q_d(1);
    csv.all(tau).end();
    return tau;
  });
}

void run_p2(double seconds, const std::string& path) {
  namespace p2 = scenarios::p2;
  const Model iiwa = load_urdf(robot_path("iiwa7.urdf"));
  p2::Observer observer(iiwa);
  Simulation sim(iiwa);
  sim.set_state(p2::initial_q(), p2::Vector7d::Zero());
  Csv csv(path, {"t", "x", "y", "z", "l0", "l1", "l2", "l3", "x_d", "y_d", "z_d", "l0_d", "l1_d", "l2_d", "l3_d",
                 "position_error", "orientation_error", "q1", "q2", "q3", "q4", "q5", "q6", "q7", "tau1", "tau2",
                 "tau3", "tau4", "tau5", "tau6", "tau7"});
  simulate(sim, seconds, [&](double t) {
    hw2::p2::Goal g = p2::goal(t);
    g.xddot_d = hw2::p2::desired_acceleration(t);
    const hw2::p2::State& s = observer.observe(t, sim.q(), sim.qdot(), g.x_d.tail<4>());
    const p2::Vector7d tau = hw2::p2::control(s, g);
    csv << t;
    csv.all(s.x_p).all(s.lambda).all(g.x_d) << (s.x_p - g.x_d.head<3>()).norm()
                                               << rotation_angle_between(s.lambda, g.x_d.tail<4>());
    csv.all(s.q).all(tau).end();
    return tau;
  });
}

void run_p3(double seconds, const std::string& path) {
  namespace p3 = scenarios::p3;
  const Model iiwa = load_urdf(robot_path("iiwa7.urdf"));
  p3::Observer observer(iiwa);
  Simulation sim(iiwa);
  sim.add_plane(-Eigen::Vector3d::UnitX(), -0.05, Material{0.0, 0.0});  // the plane x = 0.05
  sim.set_state(p3::initial_q(), p3::Vector7d::Zero());
  const int tool = sim.link_body("link7");
  Csv csv(path, {"t", "x", "y", "z", "l0", "l1", "l2", "l3", "y_d", "z_d", "l0_d", "l1_d", "l2_d", "l3_d", "Fx", "Fy",
                 "Fz", "Mx", "My", "Mz", "contact_points", "force_error", "tilt", "rotation_x_error", "q1", "q2",
                 "q3", "q4", "q5", "q6", "q7", "tau1", "tau2", "tau3", "tau4", "tau5", "tau6", "tau7"});
  simulate(sim, seconds, [&](double t) {
    const hw2::p3::Goal g = p3::goal(t);
    const hw2::p3::State& s = observer.observe(t, sim.q(), sim.qdot(), g.x_d.tail<4>());
    const p3::Vector7d tau = hw2::p3::control(s, g);
    // What the tool applies to the plane: the opposite of the plane's wrench on link7.
    const Eigen::Vector3d force = -sim.contact_wrench(tool).force, moment = -sim.contact_wrench(tool).moment;
    int points = 0;
    for (const Contact& c : sim.contacts()) points += c.body == tool ? 1 : 0;
    const Eigen::Vector3d axis = rotation_matrix(s.lambda).col(2);  // the tool's normal
    // The log's desired values are the problem set's (problem 2's y, z and lambda_d): the goal's
    // probes in the force directions (x_d along x, lambda_d's tilt) are the controller's input.
    const p3::Vector7d x_d = scenarios::p2::desired(t).x;
    csv << t;
    csv.all(s.x_p).all(s.lambda).all(x_d.tail<6>()).all(force).all(moment) << points << force.x() - 10.0
        << std::atan2(axis.cross(Eigen::Vector3d::UnitX()).norm(), axis.x())
        << orientation_error(s.lambda, x_d.tail<4>()).x();
    csv.all(s.q).all(tau).end();
    return tau;
  });
}

void run_p4(const std::string& run, double seconds, const std::string& path) {
  namespace p4 = scenarios::p4;
  const hw2::p4::Target target = run[0] == 'z' ? hw2::p4::Target::kAlongZ0 : hw2::p4::Target::kAlongY0;
  const bool plain = run.size() > 1;
  const Model rrr = load_urdf(robot_path("rrr.urdf"));
  p4::Observer observer(rrr);
  Simulation sim(rrr);
  sim.set_state(p4::initial_q(target), Eigen::Vector3d::Zero());
  const hw2::p4::Goal g = p4::goal(target);
  Csv csv(path, {"t", "x", "y", "z", "x_d", "y_d", "z_d", "error", "q1", "q2", "q3", "tau1", "tau2", "tau3"});
  simulate(sim, seconds, [&](double t) {
    const hw2::p4::State& s = observer.observe(t, sim.q(), sim.qdot());
    const Eigen::Vector3d tau =
        plain ? p4::plain_control(s, observer.exact(), g) : hw2::p4::control(target, s, g);
    csv << t;
    csv.all(s.x).all(g.x_d) << (s.x - g.x_d).norm();
    csv.all(s.q).all(tau).end();
    return tau;
  });
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: " << argv[0] << " PROBLEM RUN SECONDS CSV\n";
    return 2;
  }
  const std::string problem = argv[1], run = argv[2], path = argv[4];
  const double seconds = std::stod(argv[3]);
  try {
    if (problem == "1b") run_p1b(run, seconds, path);
    else if (problem == "2") run_p2(seconds, path);
    else if (problem == "3") run_p3(seconds, path);
    else if (problem == "4") run_p4(run, seconds, path);
    else throw std::invalid_argument("unknown problem '" + problem + "'");
  } catch (const std::exception& e) {
    std::cerr << argv[0] << ": " << e.what() << "\n";
    return 1;
  }
  return 0;
}
