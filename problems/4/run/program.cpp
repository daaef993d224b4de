// hw2-p4 [z|y|all] [options]: problem 4 on the simulated 3R elbow arm. Prints the answers of
// exercises/p4.cpp (hw2-p4) or solutions/p4.cpp (hw2-p4-sol) to questions i-iv at
// theta = (0, 90 deg, 0), then runs question v's controller and the plain operational-space
// controller from the same start, side by side.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <problems/4/contract.hpp>
#include "opspace/math/constants.hpp"
#include <problems/4/run/scenario.hpp>
#include <problems/4/run/pictures.hpp>
#include "opspace/scenarios/watchdog.hpp"
#include "opspace/visuals/visuals.hpp"
#include "opspace/model/urdf.hpp"

#include "opspace/programs/cli.hpp"
#include "command.hpp"
#include "reference_runs.hpp"

#ifdef OPSPACE_LIVE
#include <problems/4/run/lab.hpp>

#include "opspace/programs/live.hpp"
#endif

namespace programs = opspace::programs;

namespace {

namespace p4 = opspace::scenarios::p4;
namespace hw = opspace::hw2::p4;
using hw::Target;

int usage(const char* program, int code) {
  (code ? std::cerr : std::cout)
      << "usage: " << program << " [z|y|all] [--duration SECONDS] [--no-plots] [--no-replay] [--live [--port N]]\n"
      << "       [--test NAME [--seed N]]   replay a graded test's run, as the grader's report prints it\n"
      << "  z    question v: move the tip 10 cm down along Z0 (elbow lock)\n"
      << "  y    question v: move the tip 10 cm along Y0 (overhead lock)\n"
      << "  all  both (default)\n"
      << "  --duration  simulated seconds per run (default " << p4::kDuration << ", at most " << programs::kMaxDuration << ")\n"
      << "Logs: out/" << programs::program_name(program) << "-<z|y>.csv (the controller), out/" << programs::program_name(program)
      << "-<z|y>-plain.csv in the repository;\n"
      << "plots and a 3D replay page out/" << programs::program_name(program) << "-<z|y>-* next to them (docs/visuals.md)\n"
      << "  --live      question v live in the browser toward z (or y if named first): drag the arm, switch to\n"
      << "              the plain law (docs/live.md); until Ctrl-C, or --duration. --port N: its port\n";
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

Eigen::Matrix3d projector(const hw::Directions& d) {
  if (d.count < 0 || d.count > 3) return Eigen::Matrix3d::Constant(std::nan(""));
  return d.u.leftCols(d.count) * d.u.leftCols(d.count).transpose();
}

/// "ok" when the two sets of directions span the same subspace (u u^T does not depend on the
/// signs or the basis; 1e-6 is far above the SVDs' round-off, far below a wrong direction).
const char* same_span(const hw::Directions& a, const hw::Directions& b) {
  return a.count == b.count && (projector(a) - projector(b)).cwiseAbs().maxCoeff() < 1e-6 ? "ok" : "DIFFERS";
}

/// Questions i-iv at the singular configuration, each answer beside the reference's.
void questions_i_to_iv() {
  const opspace::Model rrr = opspace::load_urdf(opspace::robot_path(p4::kRobotFile));
  opspace::Data data(rrr);
  const hw::Kinematics k = p4::kinematics(rrr, data, p4::singular_q());
  std::cout << "questions i-iv at theta = (0, 90 deg, 0), tip at " << vec(k.x) << " m\n";
  programs::Verdict table("reference", "your answer", "");
  table.section("");
  const int dof = hw::degrees_of_freedom(k);
  table.row("i. tip degrees of freedom", std::to_string(dof), "", std::to_string(reference::p4_degrees_of_freedom()),
            dof == reference::p4_degrees_of_freedom() ? "ok" : "DIFFERS");
  const auto answer = [&](const std::string& what, const hw::Directions& mine, const hw::Directions& ref) {
    table.row(what, directions(mine), "", directions(ref), same_span(mine, ref));
  };
  answer("ii. singular directions", hw::singular_directions(k), reference::p4_singular_directions());
  answer("iii. moving directions", hw::moving_directions(k), reference::p4_moving_directions());
  answer("iii. rotation axes", hw::rotation_axes(k), reference::p4_rotation_axes());
  const char* axes[] = {"X0", "Y0", "Z0"};
  for (int axis : {2, 1, 0}) {
    const opspace::SingularityType mine = hw::singularity_type(k, Eigen::Vector3d::Unit(axis));
    table.row(std::string("iv. ") + axes[axis] + " is", type_name(mine), "",
              type_name(reference::p4_type(axis)), mine == reference::p4_type(axis) ? "ok" : "DIFFERS");
  }
  table.note("directions agree when they span the same subspace: signs and bases may differ");
  table.print(std::cout, "bash scripts/grade --problem 4 says which test and why");
}

std::string reach(const p4::Summary& s) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);
  if (s.reach_time < 0) out << "never"; else out << s.reach_time << " s";
  return out.str();
}

std::string final_q(const p4::Result& r) {
  return r.samples.empty() ? "-" : vec(r.samples.back().q * 180.0 / opspace::kPi, 1);
}

/// Question v toward `target`: your controller beside the grader's bounds and the reference,
/// then the plain controller from the same start.
void side_by_side(Target target, const p4::Result& mine, const p4::Result& plain, double duration) {
  const p4::Summary& s = mine.summary;
  const p4::Summary ref = reference::p4(target);
  std::cout << "\nquestion v, " << p4::describe(target) << ": target " << vec(p4::goal(target).x_d) << " m\n";
  if (std::abs(duration - reference::kP4Duration) > 1e-9) {
    std::cout << "note: the grader and the reference run " << programs::show(reference::kP4Duration, programs::kSeconds)
              << "; over " << programs::show(duration, programs::kSeconds) << " the comparison below is only indicative\n";
  }
  programs::Verdict table(programs::reference_heading(reference::kP4Duration), "your controller");
  table.section("");
  const bool reached = s.reach_time >= 0 && s.reach_time <= p4::kReachTimeMax;
  table.row("reached within " + programs::show(p4::kReachTolerance, programs::kMm) + " from", reach(s),
            "<= " + programs::show_bound(p4::kReachTimeMax, programs::kSeconds), reach(ref), reached ? "ok" : "MISSES");
  table.shown("final error", s.final_error, ref.final_error, programs::kMm);
  table.row("peak joint torque", programs::show(s.peak_torque, programs::kNewtonMetre) + programs::joint(s.peak_torque_joint),
            "<= " + programs::show_bound(p4::kPeakTorqueMax, programs::kNewtonMetre),
            programs::show(ref.peak_torque, programs::kNewtonMetre) + programs::joint(ref.peak_torque_joint),
            s.peak_torque <= p4::kPeakTorqueMax ? "ok" : "MISSES");
  table.shown("torques clamped to limits", static_cast<double>(s.clamped_steps), static_cast<double>(ref.clamped_steps),
              programs::kJointSteps);
  table.row("final joint angles (deg)", final_q(mine), "not graded",
            vec(reference::p4_final_q(target) * 180.0 / opspace::kPi, 1));
  table.print(std::cout, "bash scripts/grade --problem 4 says which test and why");
  const p4::Summary& p = plain.summary;
  std::cout << "the plain controller from the same start (the library's, not yours): reached " << reach(p)
            << ", final error " << programs::show(p.final_error, programs::kMm) << ",\n  peak torque "
            << programs::show(p.peak_torque, programs::kNewtonMetre) << programs::joint(p.peak_torque_joint) << ", "
            << programs::show(static_cast<double>(p.clamped_steps), programs::kJointSteps) << " clamped, final q "
            << final_q(plain) << " deg\n  expected: without the self-motion potential "
            << (target == Target::kAlongZ0 ? "it needs torques beyond the limits"
                                           : "the arm's plane never turns toward Y0")
            << " (the grader checks that contrast)\n";
  if (!mine.failure.empty()) std::cout << "  your run stopped early: " << mine.failure << "\n";
  if (!plain.failure.empty()) std::cout << "  the plain run stopped early: " << plain.failure << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  programs::P4Command command;
  command.options.run.duration = p4::kDuration;
  const int code = programs::parse_p4(argc, argv, &usage, command);
  if (code >= 0) return code;
  programs::Options& options = command.options;
  if (!programs::watchdog_from_environment(argv[0], options)) return 2;
  programs::start_replay(options, "4", p4::Scenario::kGradedDuration);
  std::cout << "problem 4, 3R elbow arm (" << OPSPACE_GRADED_LIBRARY << ")\n";
  if (options.live) {  // question v toward the first target named (z by default)
#ifdef OPSPACE_LIVE
    return programs::guarded(argv[0], [&] {
      const Target target = command.targets.front();
      opspace::live::P4Lab lab("hw2-p4", target, &hw::control);
      const std::string prefix = programs::output_path(programs::program_name(argv[0]) + (target == Target::kAlongZ0 ? "-z" : "-y"));
      return programs::serve_live(
          lab, options, prefix,
          [&] { return p4::figures(target, lab.result(), lab.result()); },
          [&] { return p4::replay_scene(target, lab.result(), lab.result()); });
    });
#else
    return programs::no_live(argv[0]);
#endif
  }
  return programs::guarded(argv[0], [&] {
    {
      // Your functions of questions i-iv run outside any closed loop: watched as one step.
      opspace::scenarios::Watchdog watchdog(options.run.watchdog, "problem 4, questions i-iv");
      questions_i_to_iv();
    }
    bool ok = true;
    for (Target target : command.targets) {
      const std::string name = target == Target::kAlongZ0 ? "z" : "y";
      options.run.progress = &std::cerr;
      options.run.label = "hw2-p4";
      const std::string prefix = programs::output_path(programs::program_name(argv[0]) + "-" + name);
      options.run.csv_path = prefix + ".csv";
      const p4::Result mine = p4::run(target, &hw::control, options.run);
      options.run.csv_path = prefix + "-plain.csv";
      const p4::Result plain = p4::run_plain(target, options.run);
      side_by_side(target, mine, plain, options.run.duration);
      std::cout << "  logs: " << prefix << ".csv, " << prefix << "-plain.csv\n";
      // --test: the value the report's figure ends with (problems/4/grade/graded.cpp)
      if (!mine.samples.empty())
        programs::print_final(options, "tip error |x - x_d| " + p4::describe(target), p4::tip_error(target, mine.samples.back()), "m");
      // After the runs: drawing never slows the control loop.
      if (!mine.samples.empty()) {
        programs::publish(
            options, prefix, [&] { return p4::figures(target, mine, plain); },
            [&] { return p4::replay_scene(target, mine, plain); });
      }
      ok = ok && mine.failure.empty();
    }
    return ok ? 0 : 1;
  });
}
