// hw2-p3 [options]: problem 3 on the simulated KUKA iiwa pushing on the plane x = 0.05, with the
// functions of exercises/p3.cpp (hw2-p3) or solutions/p3.cpp (hw2-p3-sol).
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include <problems/3/contract.hpp>
#include <problems/3/run/scenario.hpp>
#include <problems/3/run/pictures.hpp>
#include "opspace/visuals/visuals.hpp"

#include "opspace/programs/cli.hpp"
#include "opspace/programs/program.hpp"
#include "reference_runs.hpp"

#ifdef OPSPACE_LIVE
#include <problems/3/run/lab.hpp>
#endif

namespace programs = opspace::programs;

namespace {

namespace p3 = opspace::scenarios::p3;

int usage(const char* program, int code) {
  (code ? std::cerr : std::cout)
      << "usage: " << program << " [--duration SECONDS] [--csv PATH] [--no-plots] [--no-replay] [--live [--port N]]\n"
      << "       [--test NAME [--seed N]]   replay a graded test's run, as the grader's report prints it\n"
      << "  link7's tool pushes 10 N on the plane x = 0.05 and tracks y_d, z_d and the rotation about x\n"
      << "  --duration  simulated seconds (default " << p3::kDefaultDuration << ", at most " << programs::kMaxDuration << ")\n"
      << "  --csv       log file (default out/" << programs::program_name(program) << ".csv in the repository); the plots (PNG, SVG) and the replay page\n"
      << "              (HTML) are written next to it, named after it (docs/visuals.md)\n"
      << "  --no-plots, --no-replay   skip the PNG/SVG plots, the 3D replay page\n"
      << "  --live      run in real time in the browser, push the arm with the mouse (docs/live.md); until\n"
      << "              Ctrl-C, or --duration simulated seconds. --port N: its port (default: a free one)\n";
  return code;
}

std::string fixed(double v, int decimals, const char* unit) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << v << unit;
  return s.str();
}

std::string contact_time(const p3::Summary& s) {
  return s.first_contact_time < 0 ? "never" : "t = " + fixed(s.first_contact_time, 3, " s");
}

std::string x_range(const p3::Summary& s) {
  return fixed(1e3 * s.x_min, 3, "") + " to " + fixed(1e3 * s.x_max, 3, " mm");
}

/// The run's results beside the grader's bounds and the reference run.
void print_summary(const p3::Result& r, double duration, const std::string& csv) {
  const p3::Summary& s = r.summary;
  const p3::Summary ref = reference::p3();
  programs::print_summary_start(s.time_reached, duration, reference::kP3Duration);
  programs::Verdict table(programs::reference_heading(reference::kP3Duration));
  table.section("contact");
  table.row("first push on the plane", contact_time(s), "graded: must touch", contact_time(ref),
            s.first_contact_time >= 0 ? "ok" : "MISSES");
  table.section("after " + programs::show(p3::kSettleTime, programs::kSeconds));
  table.at_most("mean |F_x - 10 N|", s.force_error_mean, p3::kForceErrorMeanMax, ref.force_error_mean,
                programs::kNewton);
  table.shown("mean F_x", s.force_mean, ref.force_mean, programs::kNewton);
  table.shown("peak |F_x - 10 N|, one step", s.force_error_max, ref.force_error_max, programs::kNewton);
  table.shown("peak |F_x - 10 N|, 10 ms mean", s.force_error_max_10ms, ref.force_error_max_10ms, programs::kNewton);
  table.note("single steps scatter: the solver shares the push unevenly among the disc's contact points");
  table.at_most("steps without contact", static_cast<double>(s.contact_lost_samples),
                static_cast<double>(p3::kContactLostSamplesMax), static_cast<double>(ref.contact_lost_samples),
                programs::kSteps);
  table.shown("moment |(M_y, M_z)|, max", s.moment_yz_max, ref.moment_yz_max, programs::kNewtonMetre);
  table.at_most("y, z tracking error, RMS", s.yz_error_rms, p3::kYzErrorRmsMax, ref.yz_error_rms, programs::kMm);
  table.shown("y, z tracking error, max", s.yz_error_max, ref.yz_error_max, programs::kMm);
  table.at_most("rotation-about-x error, RMS", s.rotation_x_error_rms, p3::kRotationXErrorRmsMax,
                ref.rotation_x_error_rms, programs::kDegrees);
  table.shown("rotation-about-x error, max", s.rotation_x_error_max, ref.rotation_x_error_max, programs::kDegrees);
  table.at_most("tool tilt, max", s.tilt_max, p3::kTiltMax, ref.tilt_max, programs::kDegrees);
  table.shown("tool tilt, RMS", s.tilt_rms, ref.tilt_rms, programs::kDegrees);
  table.row("link7's origin along x", x_range(s), "not graded", x_range(ref));
  table.note("0 puts the tool face on the plane x = 0.05");
  table.section("over the whole run");
  programs::add_torque_rows(table, s, ref);
  table.print(std::cout, "bash scripts/grade --problem 3 says which test and why");
  programs::print_summary_end(r, csv);
}

/// With --test: the values the report's figures end with (problems/3/grade/graded.cpp).
void print_finals(const programs::Options& options, const p3::Result& r) {
  const p3::Sample& last = r.samples.back();
  programs::print_final(options, "force error |F_x - 10 N|", p3::force_error(last), "N");
  programs::print_final(options, "|(y - y_d, z - z_d)|", p3::yz_error(last), "m");
  programs::print_final(options, "rotation-about-x error", p3::rotation_x_error(last), "rad");
}

/// hw2-p3, described once: programs::run_program() is its main.
programs::ScenarioProgram<p3::Scenario> program() {
  programs::ScenarioProgram<p3::Scenario> program;
  program.name = "hw2-p3";
  program.problem = "3";
  program.heading =
      std::string("problem 3, iiwa unified motion and force control against a plane (") + OPSPACE_GRADED_LIBRARY + ")";
  program.duration = p3::kDefaultDuration;
  program.usage = &usage;
  program.scenario = [] { return p3::Scenario(&opspace::hw2::p3::control); };
  program.summary = &print_summary;
  program.finals = &print_finals;
  program.figures = [](const p3::Result& r, const p3::Scenario&) { return p3::figures(r); };
  program.replay_scene = [](const p3::Result& r, const p3::Scenario&) { return p3::replay_scene(r); };
#ifdef OPSPACE_LIVE
  program.lab = [](const std::string& name) {
    return std::make_unique<opspace::live::P3Lab>(name, &opspace::hw2::p3::control);
  };
#endif
  return program;
}

}  // namespace

int main(int argc, char** argv) { return programs::run_program(argc, argv, program()); }
