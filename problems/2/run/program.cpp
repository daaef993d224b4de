// hw2-p2 [options]: problem 2 on the simulated KUKA iiwa with the functions of exercises/p2.cpp
// (hw2-p2) or solutions/p2.cpp (hw2-p2-sol).
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

#include <problems/2/contract.hpp>
#include <problems/2/run/scenario.hpp>
#include <problems/2/run/pictures.hpp>
#include "opspace/visuals/visuals.hpp"

#include "opspace/programs/cli.hpp"
#include "opspace/programs/program.hpp"
#include "reference_runs.hpp"

#ifdef OPSPACE_LIVE
#include <problems/2/run/lab.hpp>
#endif

namespace programs = opspace::programs;

namespace {

namespace p2 = opspace::scenarios::p2;

int usage(const char* program, int code) {
  return programs::scenario_usage(program, code, "link7 of the iiwa tracks x_d(t) and lambda_d(t) of problem 2",
                             p2::kDefaultDuration, true);
}

/// The run's results beside the grader's bounds and the reference run.
void print_summary(const p2::Result& r, double duration, const std::string& csv) {
  const p2::Summary& s = r.summary;
  const p2::Summary ref = reference::p2();
  programs::print_summary_start(s.time_reached, duration, reference::kP2Duration);
  programs::Verdict table(programs::reference_heading(reference::kP2Duration));
  table.section("after " + programs::show(p2::kSettleTime, programs::kSeconds));
  table.at_most("position error, RMS", s.position_error_rms, p2::kPositionErrorRmsMax, ref.position_error_rms,
                programs::kMm);
  table.shown("position error, max", s.position_error_max, ref.position_error_max, programs::kMm);
  table.at_most("orientation error, RMS", s.orientation_error_rms, p2::kOrientationErrorRmsMax,
                ref.orientation_error_rms, programs::kDegrees);
  table.shown("orientation error, max", s.orientation_error_max, ref.orientation_error_max, programs::kDegrees);
  table.section("over the whole run");
  table.at_most("largest lambda step (1 ms)", s.lambda_step_max, p2::kLambdaStepMax, ref.lambda_step_max, programs::kNone);
  // The grader bounds how far a joint goes past its limit: -margin.
  const auto past = [](const p2::Summary& x) {
    return x.joint_limit_margin < 0 ? programs::show(-x.joint_limit_margin, programs::kDegrees) + programs::joint(x.joint_limit_joint)
                                    : "none (" + programs::show(x.joint_limit_margin, programs::kDegrees) + " inside)";
  };
  const bool within = -s.joint_limit_margin <= p2::kJointLimitExcessMax;
  table.row("furthest past a joint limit", past(s), "<= " + programs::show_bound(p2::kJointLimitExcessMax, programs::kDegrees),
            past(ref), within ? "ok" : "MISSES");
  if (ref.joint_limit_margin < 0) {
    table.note("expected: the law has no joint-limit task and the simulation enforces no limit, so the");
    table.note("reference too takes joint " + std::to_string(ref.joint_limit_joint + 1) +
               " past its limit at the far end of the y sweep (problems/2/guide.md)");
  }
  if (s.time_reached >= p2::kSettleTime + p2::kPeriod) {
    table.row("joint drift over the last period", programs::show(s.joint_drift_per_period, programs::kDegrees) +
                                                      programs::joint(s.joint_drift_joint),
              "<= " + programs::show_bound(p2::kJointDriftPerPeriodMax, programs::kDegrees),
              programs::show(ref.joint_drift_per_period, programs::kDegrees) + programs::joint(ref.joint_drift_joint),
              s.joint_drift_per_period <= p2::kJointDriftPerPeriodMax ? "ok" : "MISSES");
  } else {
    table.row("joint drift over the last period", "(run too short)",
              "<= " + programs::show_bound(p2::kJointDriftPerPeriodMax, programs::kDegrees),
              programs::show(ref.joint_drift_per_period, programs::kDegrees) + programs::joint(ref.joint_drift_joint));
  }
  programs::add_torque_rows(table, s, ref);
  table.print(std::cout, "bash scripts/grade --problem 2 says which test and why");
  programs::print_summary_end(r, csv);
}

/// With --test: the values the report's figures end with (problems/2/grade/graded.cpp).
void print_finals(const programs::Options& options, const p2::Result& r) {
  const p2::Sample& last = r.samples.back();
  programs::print_final(options, "position error |x_p - x_pd|", p2::position_error(last), "m");
  programs::print_final(options, "orientation error (angle of R R_d^T)", p2::orientation_angle(last), "rad");
}

/// hw2-p2, described once: programs::run_program() is its main.
programs::ScenarioProgram<p2::Scenario> program() {
  programs::ScenarioProgram<p2::Scenario> program;
  program.name = "hw2-p2";
  program.problem = "2";
  program.heading = std::string("problem 2, iiwa position + Euler-parameter tracking (") + OPSPACE_GRADED_LIBRARY + ")";
  program.duration = p2::kDefaultDuration;
  program.usage = &usage;
  program.scenario = [] { return p2::Scenario{&opspace::hw2::p2::control, &opspace::hw2::p2::desired_acceleration}; };
  program.summary = &print_summary;
  program.finals = &print_finals;
  program.figures = [](const p2::Result& r, const p2::Scenario&) { return p2::figures(r); };
  program.replay_scene = [](const p2::Result& r, const p2::Scenario&) { return p2::replay_scene(r); };
#ifdef OPSPACE_LIVE
  program.lab = [](const std::string& name) {
    return std::make_unique<opspace::live::P2Lab>(name, &opspace::hw2::p2::control,
                                                  &opspace::hw2::p2::desired_acceleration);
  };
#endif
  return program;
}

}  // namespace

int main(int argc, char** argv) { return programs::run_program(argc, argv, program()); }
