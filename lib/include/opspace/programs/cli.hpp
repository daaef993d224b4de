// What the programs of the simulated problems share, knowing none of them: the options
// --duration, --csv, --no-plots, --no-replay, --live, --port, --test and --seed (a program
// adds its own through Program::extra), the end of the run summary, the pictures after a run,
// and the error exit. tests/fuzz/fuzz_cli.cpp fuzzes the parsing.
#pragma once

#include <functional>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "opspace/visuals/plot.hpp"
#include "opspace/visuals/replay.hpp"
#include "opspace/scenarios/common.hpp"

#include "opspace/programs/verdict.hpp"

namespace opspace::programs {

/// The longest run --duration accepts (simulated seconds): 30 times the longest default (20 s).
/// A run records one sample per 1 ms step and reserves them all at its start: the limit keeps
/// that allocation under 200 MB (problem 3's samples, 304 bytes, are the largest) instead of
/// the size a number on the command line claims.
inline constexpr double kMaxDuration = 600.0;

/// What a program's command line sets.
struct Options {
  opspace::scenarios::RunOptions run;  ///< duration and CSV log of a run
  bool plots = true;                   ///< --no-plots: no PNG/SVG plots
  bool replay = true;                  ///< --no-replay: no 3D replay page
  bool live = false;                   ///< --live: served live in the browser (docs/live.md)
  int port = 0;                        ///< --port N: the live page's port (0: a free one)
  bool duration_given = false;         ///< --duration was on the command line
  /// --test NAME: replay the graded test NAME's run, as the grader ran it (the report's
  /// "replay it" line): its duration, and its final values printed in full.
  std::string test;
  unsigned long long seed = 0;  ///< --seed N: the grading's seed, which the report names
};

/// The program's side of parse(): its usage text and the options only it takes.
struct Program {
  /// Prints the usage of `program` to stdout (code 0) or stderr and returns `code`.
  int (*usage)(const char* program, int code) = nullptr;
  bool help = true;  ///< --help and -h print the usage (exit 0)
  bool csv = true;   ///< --csv PATH sets the log
  /// Takes one of the program's own arguments; returns false for an unknown one.
  std::function<bool(const std::string& arg)> extra;
};

/// Parses argv[first] .. argv[argc - 1] into `options`: --help, -h, --duration SECONDS (in
/// (0, kMaxDuration]), --csv PATH (not empty), --no-plots, --no-replay, --live, --port N (0 to
/// 65535, with --live only), --test NAME (not with --duration), --seed N (a positive whole
/// number), then program.extra.
/// Returns -1 when the program goes on, otherwise its exit code: 0 after --help, 2 after a bad
/// argument (a message naming it on stderr).
int parse(int argc, char** argv, int first, const Program& program, Options& options);

/// Prints "program: message" on stderr and returns 2, the exit code of a bad argument.
int refuse(const char* program, const std::string& message);

/// Adds the rows every run summary ends with to `table`: peak torque and clamped steps of the
/// run `s` beside those of the reference run `ref` (the grader bounds neither, except in
/// problem 4, which adds its own row).
template <class Summary>
void add_torque_rows(Verdict& table, const Summary& s, const Summary& ref) {
  table.row("peak joint torque", show(s.peak_torque, kNewtonMetre) + joint(s.peak_torque_joint), "not graded",
            show(ref.peak_torque, kNewtonMetre) + joint(ref.peak_torque_joint));
  table.shown("torques clamped to limits", static_cast<double>(s.clamped_steps),
              static_cast<double>(ref.clamped_steps), kJointSteps);
}

/// "reference (10 s)": the heading of the reference column for runs of `duration` seconds.
std::string reference_heading(double duration);

/// Prints the lines before a run's table: how far it got ("simulated 10.00 s of 10 s") and,
/// when its duration differs from the reference run's, that the comparison is only indicative.
void print_summary_start(double time_reached, double duration, double reference_duration);

/// Prints the lines every run summary ends with: the log `csv` (unless empty) and why the run
/// stopped early (unless it did not).
template <class Result>
void print_summary_end(const Result& r, const std::string& csv) {
  if (!csv.empty()) std::cout << "log: " << csv << "\n";
  if (!r.failure.empty()) std::cout << "the run stopped early: " << r.failure << "\n";
}

/// Writes the plots `figures()` (if options.plots) and the replay page `scene()` (if
/// options.replay) named after `prefix`, printing their paths on stdout.
void publish(const Options& options, const std::string& prefix,
             const std::function<std::vector<opspace::plot::Figure>()>& figures,
             const std::function<opspace::replay::Scene()>& scene);

/// The end of a program that made one run: its plots and replay page named after `prefix`
/// (drawn after the run, so drawing never slows the control loop; a note instead when the run
/// logged no sample), then the exit code: 0 if the run reached its end, 1 if it stopped early.
template <class Result>
int finish(const Options& options, const std::string& prefix, const Result& result,
           const std::function<std::vector<opspace::plot::Figure>()>& figures,
           const std::function<opspace::replay::Scene()>& scene) {
  if (result.samples.empty()) {
    std::cout << "note:   no plots or replay: the run logged no sample\n";
    return 1;
  }
  publish(options, prefix, figures, scene);
  return result.failure.empty() ? 0 : 1;
}

/// With --test: sets the run's duration to `graded_duration`, the graded run's of problem
/// `problem` (its key, as in problems.txt; its Scenario::kGradedDuration), and prints which test
/// the run replays. The simulated scenarios draw no random input, so the seed names the grading
/// and changes nothing in the run.
void start_replay(Options& options, const std::string& problem, double graded_duration);

/// With --test: "final QUANTITY: VALUE UNIT", VALUE in full (17 digits): the last value of the
/// report's figure of QUANTITY, which a replay reproduces.
void print_final(const Options& options, const std::string& quantity, double value, const std::string& unit);

/// The usage of a program of one scenario (run_program) to stdout (code 0) or stderr: its
/// options, `what` it runs (a line), its default `duration`; --live where it has a `live` lab.
/// Returns `code`.
int scenario_usage(const char* program, int code, const std::string& what, double duration, bool live);

/// Prints on stderr that this build has no live lab and how to get it; returns 2.
int no_live(const char* program);
/// Prints on stderr that problem `problem` has no live lab (its folder declares no LAB); returns 2.
int no_lab(const char* program, const std::string& problem);

/// Returns body(); an exception instead prints "program: what" on stderr and returns 1.
int guarded(const char* program, const std::function<int()>& body);

/// The program's name as it was run (argv[0] without its folder): its files start with it, so
/// that hw2-p3 and the reference hw2-p3-sol never write over each other's log and pictures.
std::string program_name(const char* argv0);

/// The default path of the output `name` (e.g. "hw2-p3.csv"): in the repository's out/ (or in
/// $OPSPACE_OUT if set), wherever the program runs from. Relative when out/ lies below the
/// current directory ("out/hw2-p3.csv" from the repository's root), absolute otherwise.
std::string output_path(const std::string& name);

/// Sets options.run.watchdog from OPSPACE_WATCHDOG (scripts/run sets it: a run whose step
/// takes longer is stopped, scenarios/watchdog.hpp). Returns false after printing
/// "program: ..." on stderr if the variable is not a number of seconds.
bool watchdog_from_environment(const char* program, Options& options);

}  // namespace opspace::programs
