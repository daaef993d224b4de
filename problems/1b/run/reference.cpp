// Problem 1b's reference run (problems/CMakeLists.txt: REFERENCE): each PART with solutions/ at
// hw2-p1's default duration, written as reference_runs.hpp's p1b() and the live page's ghost,
// and as the guide's table (fragment p1b-reference).
#include <cstddef>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <problems/1b/contract.hpp>
#include "opspace/programs/reference_text.hpp"
#include <problems/1b/run/scenario.hpp>

namespace programs = opspace::programs;

namespace {

namespace p1b = opspace::scenarios::p1b;
using Part = opspace::hw2::p1b::Part;
using Runs = std::map<Part, p1b::Result>;

constexpr Part kParts[] = {Part::kTipPd, Part::kTipPdWithoutJointDamping, Part::kPseudoInverseNullspace,
                           Part::kDynamicallyConsistentNullspace};

Runs run_parts() {
  Runs runs;
  opspace::scenarios::RunOptions options;
  options.duration = p1b::kDefaultDuration;
  for (Part part : kParts) {
    runs[part] = p1b::run(part, &opspace::hw2::p1b::control, options);
    if (!runs[part].failure.empty()) throw std::runtime_error(p1b::describe(part) + " stopped early: " + runs[part].failure);
  }
  return runs;
}

#define OPSPACE_MEMBER(s, m) set(#m, s.m)
void members(programs::Assignments& set, const p1b::Summary& s) {
  OPSPACE_MEMBER(s, tip_error_max);
  OPSPACE_MEMBER(s, tip_error_rms);
  OPSPACE_MEMBER(s, q2_error_max);
  OPSPACE_MEMBER(s, q2_error_rms);
  programs::run_totals(set, s);
}
#undef OPSPACE_MEMBER

std::string part_condition(Part part) {
  return "part == static_cast<opspace::hw2::p1b::Part>(" + std::to_string(static_cast<int>(part)) + ")";
}

/// The live page's ghost (docs/live.md): each run's tip path, one point every kPathEvery
/// samples, in metres to the nanometre.
void tip_paths(std::ostream& out, const Runs& runs) {
  constexpr std::size_t kPathEvery = 20;  // 20 ms at the 1 ms step: 501 points per 10 s run
  const double step = runs.begin()->second.samples.at(kPathEvery).t;
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
  for (const auto& [part, r] : runs) {
    if (part == Part::kTipPdWithoutJointDamping) continue;  // not a law of the live page
    xyz.str("");
    for (std::size_t k = 0; k < r.samples.size(); k += kPathEvery) {
      const Eigen::Vector3d& x = r.samples[k].x;
      xyz << (k ? (k % (4 * kPathEvery) ? ", " : ",\n      ") : "") << x(0) << ", " << x(1) << ", " << x(2);
    }
    out << "  if (" << part_condition(part) << ") {\n"
        << "    static const double xyz[] = {\n      " << xyz.str() << "};\n    return points(xyz);\n  }\n";
  }
  out << "  return {};\n}\n\n";
}

std::string declarations(const Runs& runs) {
  std::ostringstream out;
  out << "/// Simulated seconds of problem 1b's reference runs.\n"
      << "inline constexpr double kP1bDuration = " << p1b::kDefaultDuration << ";\n\n";
  std::vector<std::pair<std::string, p1b::Summary>> parts;
  for (const auto& [part, r] : runs) parts.emplace_back(part_condition(part), r.summary);
  out << "/// solutions/' run of `part`.\n";
  programs::summary_function(out, "p1b(opspace::hw2::p1b::Part part)", "opspace::scenarios::p1b::Summary", parts, &members);
  tip_paths(out, runs);
  return out.str();
}

/// The largest joint speed of a run from 1 ms differences of q (rad/s), and its joint.
std::pair<double, int> largest_speed(const p1b::Result& r) {
  double speed = 0.0;
  int joint = 0;
  for (std::size_t k = 1; k < r.samples.size(); ++k) {
    const auto dq = (r.samples[k].q - r.samples[k - 1].q) / (r.samples[k].t - r.samples[k - 1].t);
    Eigen::Index i = 0;
    const double largest = dq.cwiseAbs().maxCoeff(&i);
    if (largest > speed) {
      speed = largest;
      joint = static_cast<int>(i);
    }
  }
  return {speed, joint};
}

std::string fragment(const Runs& runs) {
  using programs::show;
  const p1b::Result& part1 = runs.at(Part::kTipPd);
  const Eigen::Vector3d x_d = p1b::goal(0.0, p1b::initial_q()).x_d;
  std::ostringstream out;
  out << "Measured with `hw2-p1-sol` over " << show(p1b::kDefaultDuration, programs::kSeconds)
      << ", the default run and the graded one (errors after the first " << show(p1b::kSettleTime, programs::kSeconds)
      << "; the tip starts " << show((part1.samples.front().x - x_d).norm(), programs::kMm) << " from x_d):\n\n"
      << "| run | tip error | q2 tracking error | peak torque |\n|---|---|---|---|\n";
  for (Part part : kParts) {
    const p1b::Summary& s = runs.at(part).summary;
    // PART2 is chaotic: 1e-15 rad more on joint 6's start moves its max tip error by 5 % and
    // its clamped steps by 20 % (measured); the other parts do not change in 4 digits.
    const programs::Show number = part == Part::kPseudoInverseNullspace ? &programs::approx : &programs::show;
    const bool joint_task = part == Part::kPseudoInverseNullspace || part == Part::kDynamicallyConsistentNullspace;
    const std::string name = part == Part::kTipPdWithoutJointDamping ? "PART1 without joint damping"
                                                                     : p1b::describe(part).substr(0, 5);
    out << "| " << name << " | " << programs::max_rms(s.tip_error_max, s.tip_error_rms, programs::kMm, number) << " | "
        << (joint_task ? "max " + number(s.q2_error_max, programs::kRad) : "(no joint task)") << " | "
        << programs::torque(s.peak_torque, s.peak_torque_joint, s.clamped_steps, number) << " |\n";
  }
  const auto [speed, joint] = largest_speed(runs.at(Part::kPseudoInverseNullspace));
  out << "\nPART2's fastest joint, joint " << joint + 1 << ", reaches " << programs::approx(speed, {"rad/s", 1.0})
      << " (1 ms differences of q).\n"
         "PART2 is chaotic: \"~\" marks values that round-off changes by percents (the last bit of\n"
         "one starting angle moves its tip error by 5 %).\n";
  return out.str();
}

}  // namespace

programs::ReferenceText reference_run_1b() {
  const Runs runs = run_parts();
  return {{"problems/1b/contract.hpp", "problems/1b/run/scenario.hpp"}, declarations(runs), {{"p1b-reference", fragment(runs)}}};
}
