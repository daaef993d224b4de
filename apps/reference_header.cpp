// hw2-reference's reference_runs.hpp (reference.cpp): the Summary of every reference run and
// problem 4's answers i-iv as exact C++ (hexadecimal floating literals), which the hw2-p*
// programs print beside their own values.
#include <ios>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <opspace/hw2/p4.hpp>
#include <problems/1b/scenario.hpp>
#include <problems/2/scenario.hpp>
#include <problems/3/scenario.hpp>
#include <problems/4/scenario.hpp>
#include <opspace/model/urdf.hpp>

#include "reference.hpp"

namespace hw2_reference {

namespace {

/// C++ assignments of a Summary's members, exact (hexadecimal floating literals).
class Assignments {
 public:
  explicit Assignments(std::ostream& out) : out_(out) {}
  void operator()(const char* member, double v) {
    std::ostringstream hex;
    hex << std::hexfloat << v;
    out_ << "    s." << member << " = " << hex.str() << ";\n";
  }
  void operator()(const char* member, long v) { out_ << "    s." << member << " = " << v << ";\n"; }
  void operator()(const char* member, int v) { out_ << "    s." << member << " = " << v << ";\n"; }

 private:
  std::ostream& out_;
};

#define OPSPACE_MEMBER(s, m) set(#m, s.m)

void members(Assignments& set, const p1b::Summary& s) {
  OPSPACE_MEMBER(s, tip_error_max);
  OPSPACE_MEMBER(s, tip_error_rms);
  OPSPACE_MEMBER(s, q2_error_max);
  OPSPACE_MEMBER(s, q2_error_rms);
  OPSPACE_MEMBER(s, peak_torque);
  OPSPACE_MEMBER(s, peak_torque_joint);
  OPSPACE_MEMBER(s, clamped_steps);
  OPSPACE_MEMBER(s, time_reached);
}

void members(Assignments& set, const p2::Summary& s) {
  OPSPACE_MEMBER(s, position_error_max);
  OPSPACE_MEMBER(s, position_error_rms);
  OPSPACE_MEMBER(s, orientation_error_max);
  OPSPACE_MEMBER(s, orientation_error_rms);
  OPSPACE_MEMBER(s, lambda_norm_error_max);
  OPSPACE_MEMBER(s, lambda_step_max);
  OPSPACE_MEMBER(s, lambda_dot_lambda_d_min);
  OPSPACE_MEMBER(s, joint_limit_margin);
  OPSPACE_MEMBER(s, joint_limit_joint);
  OPSPACE_MEMBER(s, joint_drift_per_period);
  OPSPACE_MEMBER(s, joint_drift_joint);
  OPSPACE_MEMBER(s, peak_torque);
  OPSPACE_MEMBER(s, peak_torque_joint);
  OPSPACE_MEMBER(s, clamped_steps);
  OPSPACE_MEMBER(s, time_reached);
}

void members(Assignments& set, const p3::Summary& s) {
  OPSPACE_MEMBER(s, first_contact_time);
  OPSPACE_MEMBER(s, contact_lost_samples);
  OPSPACE_MEMBER(s, force_error_mean);
  OPSPACE_MEMBER(s, force_error_max);
  OPSPACE_MEMBER(s, force_error_max_10ms);
  OPSPACE_MEMBER(s, force_mean);
  OPSPACE_MEMBER(s, moment_yz_max);
  OPSPACE_MEMBER(s, yz_error_rms);
  OPSPACE_MEMBER(s, yz_error_max);
  OPSPACE_MEMBER(s, rotation_x_error_rms);
  OPSPACE_MEMBER(s, rotation_x_error_max);
  OPSPACE_MEMBER(s, tilt_max);
  OPSPACE_MEMBER(s, tilt_rms);
  OPSPACE_MEMBER(s, x_min);
  OPSPACE_MEMBER(s, x_max);
  OPSPACE_MEMBER(s, peak_torque);
  OPSPACE_MEMBER(s, peak_torque_joint);
  OPSPACE_MEMBER(s, clamped_steps);
  OPSPACE_MEMBER(s, time_reached);
}

void members(Assignments& set, const p4::Summary& s) {
  OPSPACE_MEMBER(s, final_error);
  OPSPACE_MEMBER(s, reach_time);
  OPSPACE_MEMBER(s, peak_torque);
  OPSPACE_MEMBER(s, peak_torque_joint);
  OPSPACE_MEMBER(s, clamped_steps);
  OPSPACE_MEMBER(s, time_reached);
}

#undef OPSPACE_MEMBER

template <class Summary>
void summary_function(std::ostream& out, const std::string& signature, const std::string& type,
                      const std::vector<std::pair<std::string, Summary>>& cases) {
  Assignments set(out);
  out << "inline " << type << " " << signature << " {\n  " << type << " s;\n";
  for (const auto& [condition, summary] : cases) {
    if (!condition.empty()) out << "  if (" << condition << ") {\n";
    members(set, summary);
    if (!condition.empty()) out << "  }\n";
  }
  out << "  return s;\n}\n\n";
}

std::string vector3(const Eigen::Vector3d& v) {
  std::ostringstream s;
  s << std::hexfloat << "Eigen::Vector3d(" << v(0) << ", " << v(1) << ", " << v(2) << ")";
  return s.str();
}

std::string directions(const opspace::hw2::p4::Directions& d) {
  std::ostringstream s;
  s << "{" << d.count << ", (Eigen::Matrix3d() << " << std::hexfloat;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) s << (i || j ? ", " : "") << d.u(i, j);
  }
  s << ").finished()}";
  return s.str();
}

/// The live page's ghost (docs/live.md): each problem 1b run's tip path, one point every
/// kPathEvery samples, in metres to the nanometre.
void tip_paths(std::ostream& out, const Runs& runs) {
  constexpr std::size_t kPathEvery = 20;  // 20 ms at the 1 ms step: 501 points per 10 s run
  const double step = runs.p1b.begin()->second.samples.at(kPathEvery).t;
  out << "/// solutions/' tip path (m) of problem 1b under `part`, unpushed, one point every kP1bTipPathStep s\n"
      << "/// from t = 0: the live page's ghost.\n"
      << "inline constexpr double kP1bTipPathStep = " << step << ";\n"
      << "inline std::vector<Eigen::Vector3d> p1b_tip_path(opspace::hw2::p1b::Part part) {\n"
      << "  const auto points = [](const auto& xyz) {\n"
      << "    std::vector<Eigen::Vector3d> path;\n"
      << "    for (std::size_t i = 0; i + 2 < std::size(xyz); i += 3) path.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);\n"
      << "    return path;\n  };\n";
  std::ostringstream xyz;
  xyz.precision(9);
  for (const auto& [part, r] : runs.p1b) {
    if (part == Part::kTipPdWithoutJointDamping) continue;  // not a law of the live page
    xyz.str("");
    for (std::size_t k = 0; k < r.samples.size(); k += kPathEvery) {
      const Eigen::Vector3d& x = r.samples[k].x;
      xyz << (k ? (k % (4 * kPathEvery) ? ", " : ",\n      ") : "") << x(0) << ", " << x(1) << ", " << x(2);
    }
    out << "  if (part == static_cast<opspace::hw2::p1b::Part>(" << static_cast<int>(part) << ")) {\n"
        << "    static const double xyz[] = {\n      " << xyz.str() << "};\n    return points(xyz);\n  }\n";
  }
  out << "  return {};\n}\n\n";
}

}  // namespace

void write_header(const Runs& runs, const std::string& path) {
  std::ostringstream out;
  out << "// Generated at build time by hw2-reference (apps/reference_header.cpp): what solutions/ does on each\n"
         "// scenario at the programs' default durations, exactly. Do not edit.\n"
         "#pragma once\n\n"
         "#include <iterator>\n"
         "#include <vector>\n\n"
         "#include <opspace/hw2/p4.hpp>\n"
         "#include <problems/1b/scenario.hpp>\n"
         "#include <problems/2/scenario.hpp>\n"
         "#include <problems/3/scenario.hpp>\n"
         "#include <problems/4/scenario.hpp>\n\n"
         "namespace reference {\n\n";
  out << "/// Simulated seconds of the reference runs.\n"
      << "inline constexpr double kP1bDuration = " << p1b::kDefaultDuration << ";\n"
      << "inline constexpr double kP2Duration = " << p2::kDefaultDuration << ";\n"
      << "inline constexpr double kP3Duration = " << p3::kDefaultDuration << ";\n"
      << "inline constexpr double kP4Duration = " << p4::kDuration << ";\n\n";
  std::vector<std::pair<std::string, p1b::Summary>> parts;
  for (const auto& [part, r] : runs.p1b) {
    parts.emplace_back("part == static_cast<opspace::hw2::p1b::Part>(" + std::to_string(static_cast<int>(part)) + ")",
                       r.summary);
  }
  out << "/// solutions/' run of `part`.\n";
  summary_function(out, "p1b(opspace::hw2::p1b::Part part)", "opspace::scenarios::p1b::Summary", parts);
  tip_paths(out, runs);
  out << "/// solutions/' run of problem 2.\n";
  summary_function<p2::Summary>(out, "p2()", "opspace::scenarios::p2::Summary", {{"", runs.p2.summary}});
  out << "/// solutions/' run of problem 3.\n";
  summary_function<p3::Summary>(out, "p3()", "opspace::scenarios::p3::Summary", {{"", runs.p3.summary}});
  std::vector<std::pair<std::string, p4::Summary>> targets;
  for (const auto& [target, r] : runs.p4) {
    targets.emplace_back("target == static_cast<opspace::hw2::p4::Target>(" +
                             std::to_string(static_cast<int>(target)) + ")",
                         r.summary);
  }
  out << "/// solutions/' run of question v toward `target`.\n";
  summary_function(out, "p4(opspace::hw2::p4::Target target)", "opspace::scenarios::p4::Summary", targets);
  out << "/// The joint angles at the end of that run (rad).\n"
      << "inline Eigen::Vector3d p4_final_q(opspace::hw2::p4::Target target) {\n";
  for (const auto& [target, r] : runs.p4) {
    out << "  if (target == static_cast<opspace::hw2::p4::Target>(" << static_cast<int>(target) << ")) return "
        << vector3(r.samples.back().q) << ";\n";
  }
  out << "  return Eigen::Vector3d::Zero();\n}\n\n";

  // Questions i-iv at the singular configuration.
  const opspace::Model rrr = opspace::load_urdf(opspace::robot_path(p4::kRobotFile));
  opspace::Data data(rrr);
  const opspace::hw2::p4::Kinematics k = p4::kinematics(rrr, data, p4::singular_q());
  namespace hw = opspace::hw2::p4;
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
  out << "};\n  return static_cast<opspace::SingularityType>(types[axis]);\n}\n\n}  // namespace reference\n";

  std::ofstream file(path);
  file << out.str();
  if (!file) throw std::runtime_error("cannot write " + path);
}

}  // namespace hw2_reference
