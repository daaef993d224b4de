// Problem 4's reference run (problems/CMakeLists.txt: REFERENCE): solutions/' answers to
// questions i-iv at the singular configuration, and question v's runs toward each target (with
// the plain law beside them) at hw2-p4's duration, written as reference_runs.hpp's p4*() and as
// the guide's table (fragment p4-reference).
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <problems/4/contract.hpp>
#include "opspace/math/constants.hpp"
#include "opspace/model/urdf.hpp"
#include "opspace/programs/reference_text.hpp"
#include <problems/4/run/scenario.hpp>

namespace programs = opspace::programs;

namespace {

namespace p4 = opspace::scenarios::p4;
namespace hw = opspace::hw2::p4;
using Target = hw::Target;

constexpr Target kTargets[] = {Target::kAlongZ0, Target::kAlongY0};

struct Runs {
  std::map<Target, p4::Result> law, plain;  ///< question v's law and the plain law, by target
};

Runs run_targets() {
  Runs runs;
  opspace::scenarios::RunOptions options;
  options.duration = p4::kDuration;
  for (Target target : kTargets) {
    runs.law[target] = p4::run(target, &hw::control, options);
    runs.plain[target] = p4::run_plain(target, options);
    if (!runs.law[target].failure.empty())
      throw std::runtime_error("problem 4's reference run stopped early: " + runs.law[target].failure);
  }
  return runs;
}

#define OPSPACE_MEMBER(s, m) set(#m, s.m)
void members(programs::Assignments& set, const p4::Summary& s) {
  OPSPACE_MEMBER(s, final_error);
  OPSPACE_MEMBER(s, reach_time);
  programs::run_totals(set, s);
}
#undef OPSPACE_MEMBER

std::string target_condition(Target target) {
  return "target == static_cast<opspace::hw2::p4::Target>(" + std::to_string(static_cast<int>(target)) + ")";
}

std::string directions(const hw::Directions& d) {
  std::ostringstream s;
  s << "{" << d.count << ", (Eigen::Matrix3d() << ";
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) s << (i || j ? ", " : "") << programs::exact(d.u(i, j));
  }
  s << ").finished()}";
  return s.str();
}

/// Questions i-iv at the singular configuration.
void answers(std::ostream& out) {
  const opspace::Model rrr = opspace::load_urdf(opspace::robot_path(p4::kRobotFile));
  opspace::Data data(rrr);
  const hw::Kinematics k = p4::kinematics(rrr, data, p4::singular_q());
  out << "/// solutions/' answers to questions i-iv at theta = (0, 90 deg, 0).\n"
      << "inline int p4_degrees_of_freedom() { return " << hw::degrees_of_freedom(k) << "; }\n"
      << "inline opspace::hw2::p4::Directions p4_singular_directions() { return " << directions(hw::singular_directions(k))
      << "; }\n"
      << "inline opspace::hw2::p4::Directions p4_moving_directions() { return " << directions(hw::moving_directions(k))
      << "; }\n"
      << "inline opspace::hw2::p4::Directions p4_rotation_axes() { return " << directions(hw::rotation_axes(k))
      << "; }\n"
      << "/// The type of axis 0 (X0), 1 (Y0) or 2 (Z0).\n"
      << "inline opspace::SingularityType p4_type(int axis) {\n"
      << "  const int types[3] = {";
  for (int axis = 0; axis < 3; ++axis) {
    out << (axis ? ", " : "") << static_cast<int>(hw::singularity_type(k, Eigen::Vector3d::Unit(axis)));
  }
  out << "};\n  return static_cast<opspace::SingularityType>(types[axis]);\n}\n\n";
}

std::string declarations(const Runs& runs) {
  std::ostringstream out;
  out << "/// Simulated seconds of problem 4's reference runs.\n"
      << "inline constexpr double kP4Duration = " << p4::kDuration << ";\n\n";
  std::vector<std::pair<std::string, p4::Summary>> targets;
  for (const auto& [target, r] : runs.law) targets.emplace_back(target_condition(target), r.summary);
  out << "/// solutions/' run of question v toward `target`.\n";
  programs::summary_function(out, "p4(opspace::hw2::p4::Target target)", "opspace::scenarios::p4::Summary", targets,
                        &members);
  out << "/// The joint angles at the end of that run (rad).\n"
      << "inline Eigen::Vector3d p4_final_q(opspace::hw2::p4::Target target) {\n";
  for (const auto& [target, r] : runs.law) {
    out << "  if (" << target_condition(target) << ") return " << programs::exact(r.samples.back().q) << ";\n";
  }
  out << "  return Eigen::Vector3d::Zero();\n}\n\n";
  answers(out);
  return out.str();
}

std::string reach(const p4::Summary& s) { return s.reach_time < 0 ? "never" : programs::show(s.reach_time, programs::kSeconds); }

std::string fragment(const Runs& runs) {
  using programs::show;
  constexpr double kDegPerRad = 180.0 / opspace::kPi;
  std::ostringstream out;
  out << "Measured with `hw2-p4-sol` over " << show(p4::kDuration, programs::kSeconds)
      << " (\"reached\" = from when on the tip stays within " << show(p4::kReachTolerance, programs::kMm)
      << " of x_d):\n\n| run | reached | final error | peak torque requested | clamped | final q (deg) |\n"
      << "|---|---|---|---|---|---|\n";
  for (Target target : kTargets) {
    for (bool plain : {false, true}) {
      const p4::Result& r = plain ? runs.plain.at(target) : runs.law.at(target);
      const p4::Summary& s = r.summary;
      const Eigen::Vector3d q = r.samples.back().q * kDegPerRad;
      out << "| " << (target == Target::kAlongZ0 ? "Z0" : "Y0") << (plain ? ", plain" : ", question v") << " | "
          << reach(s) << " | " << show(s.final_error, programs::kMm) << " | " << show(s.peak_torque, programs::kNewtonMetre)
          << programs::joint(s.peak_torque_joint) << " | " << show(static_cast<double>(s.clamped_steps), programs::kJointSteps)
          << " | (" << programs::fixed(q(0), 1) << ", " << programs::fixed(q(1), 1) << ", " << programs::fixed(q(2), 1) << ") |\n";
    }
  }
  return out.str();
}

}  // namespace

programs::ReferenceText reference_run_4() {
  const Runs runs = run_targets();
  return {{"problems/4/contract.hpp", "problems/4/run/scenario.hpp"}, declarations(runs), {{"p4-reference", fragment(runs)}}};
}
