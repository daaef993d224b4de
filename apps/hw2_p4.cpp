// hw2-p4 [z|y|all] [options]: problem 4 on the simulated 3R elbow arm. Prints the answers of
// exercises/p4.cpp (hw2-p4) or solutions/p4.cpp (hw2-p4-sol) to questions i-iv at
// theta = (0, 90 deg, 0), then runs question v's controller and the plain operational-space
// controller from the same start, side by side.
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <opspace/hw2/p4.hpp>
#include <opspace/scenarios.hpp>
#include <opspace/scenarios/p4_visuals.hpp>
#include <opspace/visuals.hpp>
#include <opspace/urdf.hpp>

#include "cli.hpp"

namespace {

namespace p4 = opspace::scenarios::p4;
namespace hw = opspace::hw2::p4;
using hw::Target;

int usage(const char* program, int code) {
  (code ? std::cerr : std::cout)
      << "usage: " << program << " [z|y|all] [--duration SECONDS] [--no-plots] [--no-replay]\n"
      << "  z    question v: move the tip 10 cm down along Z0 (elbow lock)\n"
      << "  y    question v: move the tip 10 cm along Y0 (overhead lock)\n"
      << "  all  both (default)\n"
      << "  --duration  simulated seconds per run (default " << p4::kDuration << ", at most " << cli::kMaxDuration << ")\n"
      << "Logs: out/hw2-p4-<z|y>.csv (your controller), out/hw2-p4-<z|y>-plain.csv; plots and a 3D\n"
      << "replay page out/hw2-p4-<z|y>-* next to them (docs/visuals.md)\n";
  return code;
}

std::string vec(const Eigen::Vector3d& v, int digits = 3) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << "(" << v(0) << ", " << v(1) << ", " << v(2) << ")";
  return s.str();
}

std::string directions(const hw::Directions& d) {
  if (d.count <= 0 || d.count > 3) return d.count == 0 ? "none" : "count " + std::to_string(d.count) + "?";
  std::string out;
  for (int i = 0; i < d.count; ++i) out += (i ? ", " : "") + vec(d.u.col(i));
  return out;
}

const char* type_name(opspace::SingularityType t) {
  switch (t) {
    case opspace::SingularityType::kNone: return "not singular";
    case opspace::SingularityType::kTypeI: return "Type I";
    case opspace::SingularityType::kTypeII: return "Type II";
  }
  return "?";
}

void questions_i_to_iv() {
  const opspace::Model rrr = opspace::load_urdf(opspace::robot_path(p4::kRobotFile));
  opspace::Data data(rrr);
  const hw::Kinematics k = p4::kinematics(rrr, data, p4::singular_q());
  std::cout << "questions i-iv at theta = (0, 90 deg, 0), tip at " << vec(k.x) << " m\n"
            << "  i.   tip degrees of freedom: " << hw::degrees_of_freedom(k) << "\n"
            << "  ii.  singular directions:    " << directions(hw::singular_directions(k)) << "\n"
            << "  iii. moving directions:      " << directions(hw::moving_directions(k)) << "\n"
            << "       rotation axes:          " << directions(hw::rotation_axes(k)) << "\n"
            << "  iv.  Z0 is " << type_name(hw::singularity_type(k, Eigen::Vector3d::UnitZ()))
            << ", Y0 is " << type_name(hw::singularity_type(k, Eigen::Vector3d::UnitY()))
            << ", X0 is " << type_name(hw::singularity_type(k, Eigen::Vector3d::UnitX())) << "\n";
}

std::string reach(const p4::Summary& s) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);
  if (s.reach_time < 0) out << "never"; else out << s.reach_time << " s";
  return out.str();
}

void side_by_side(Target target, const p4::Result& mine, const p4::Result& plain) {
  const auto row = [](const std::string& what, const std::string& a, const std::string& b) {
    std::cout << "  " << std::left << std::setw(30) << what << std::setw(22) << a << b << "\n";
  };
  const auto num = [](double v, int digits, const std::string& unit) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << v << unit;
    return s.str();
  };
  std::cout << "\nquestion v, " << p4::describe(target) << ": target " << vec(p4::goal(target).x_d) << " m\n";
  row("", "your controller", "plain controller");
  row("reached within " + num(1e3 * p4::kReachTolerance, 0, " mm") + " from",
      reach(mine.summary), reach(plain.summary));
  row("final error", num(1e3 * mine.summary.final_error, 1, " mm"), num(1e3 * plain.summary.final_error, 1, " mm"));
  row("peak joint torque", num(mine.summary.peak_torque, 1, " N m (joint " + std::to_string(mine.summary.peak_torque_joint + 1) + ")"),
      num(plain.summary.peak_torque, 1, " N m (joint " + std::to_string(plain.summary.peak_torque_joint + 1) + ")"));
  row("torques clamped to limits", std::to_string(mine.summary.clamped_steps) + " joint-steps",
      std::to_string(plain.summary.clamped_steps) + " joint-steps");
  if (!mine.samples.empty() && !plain.samples.empty()) {
    const Eigen::Vector3d qa = mine.samples.back().q * 180.0 / 3.14159265358979323846;
    const Eigen::Vector3d qb = plain.samples.back().q * 180.0 / 3.14159265358979323846;
    row("final joint angles (deg)", vec(qa, 1), vec(qb, 1));
  }
  if (!mine.failure.empty()) std::cout << "  your run stopped early: " << mine.failure << "\n";
  if (!plain.failure.empty()) std::cout << "  the plain run stopped early: " << plain.failure << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  cli::P4Command command;
  command.options.run.duration = p4::kDuration;
  const int code = cli::parse_p4(argc, argv, &usage, command);
  if (code >= 0) return code;
  cli::Options& options = command.options;
  std::cout << "problem 4, 3R elbow arm (" << OPSPACE_GRADED_LIBRARY << ")\n";
  return cli::guarded(argv[0], [&] {
    questions_i_to_iv();
    bool ok = true;
    for (Target target : command.targets) {
      const std::string name = target == Target::kAlongZ0 ? "z" : "y";
      options.run.progress = &std::cerr;
      options.run.csv_path = "out/hw2-p4-" + name + ".csv";
      const p4::Result mine = p4::run(target, &hw::control, options.run);
      options.run.csv_path = "out/hw2-p4-" + name + "-plain.csv";
      const p4::Result plain = p4::run_plain(target, options.run);
      side_by_side(target, mine, plain);
      std::cout << "  logs: out/hw2-p4-" << name << ".csv, out/hw2-p4-" << name << "-plain.csv\n";
      // After the runs: drawing never slows the control loop.
      if (!mine.samples.empty()) {
        cli::publish(
            options, "out/hw2-p4-" + name, [&] { return p4::figures(target, mine, plain); },
            [&] { return p4::replay_scene(target, mine, plain); });
      }
      ok = ok && mine.failure.empty();
    }
    return ok ? 0 : 1;
  });
}
