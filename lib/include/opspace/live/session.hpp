/// @file live/session.hpp
/// A live session of one Lab: the commands of the page applied between steps, the push's
/// spring, the frames the page draws and the session's CSV log (docs/live.md). No threads and
/// no clock here: live/run.hpp paces it and serves it; a test steps it directly.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "opspace/simulation/closed_loop.hpp"
#include "opspace/live/command.hpp"
#include "opspace/live/lab.hpp"
#include "opspace/live/push.hpp"

namespace opspace::live {

/// The live log's columns after the Lab's own (the offline run's): the law, the speed, the
/// push (body, or -1, and its force, N), the number of resets before this row.
std::vector<std::string> session_columns(const Lab& lab);

/// One Lab, driven by commands: see the file comment.
class Session {
 public:
  /// Drives `lab` (which must outlive the session) from its start; logs to `csv_path` unless
  /// empty; pushes with `spring`.
  Session(Lab& lab, const std::string& csv_path, const Spring& spring = {});

  /// Reads `body` (POST /command) and queues it: any thread. Throws CommandError.
  void submit(std::string_view body);
  /// Applies the queued commands, in order: the simulation thread, between steps. Returns how
  /// many it applied.
  int apply_queued();
  /// Applies one command now.
  void apply(const Command& command);

  /// One step of dt unless paused or stopped by an error: the Lab's tick, its log row, the
  /// push's force, the simulation's step. An exception stops the run with its message in
  /// error() (and on the terminal) until a reset; it never escapes. With `advance` false, the
  /// tick and its log row only (an offline run's last instant).
  void step(bool advance = true);
  /// The frame the page draws now (JSON, docs/live.md#protocol), with the plot samples since
  /// the previous frame and the measured real-time factor `rtf`.
  std::string frame(double rtf);

  bool paused() const { return paused_; }          ///< by the page
  double speed() const { return speed_; }          ///< target speed, times real time
  const std::string& error() const { return error_; }  ///< what stopped the run, or empty
  double time() const;                             ///< the simulation's time (s)
  double dt() const;                               ///< its step (s)
  long resets() const { return resets_; }          ///< resets so far
  const Lab& lab() const { return lab_; }          ///< the problem

 private:
  void reset();
  void release();
  Lab& lab_;
  Spring spring_;
  CommandLimits limits_;
  std::unique_ptr<CsvLog> csv_;
  std::unique_ptr<Pusher> pusher_;  // rebuilt with the Lab's simulation
  std::mutex queue_mutex_;
  std::vector<Command> queue_;

  bool paused_ = false;
  double speed_ = 1.0;
  int law_ = 0;
  std::vector<double> gains_;
  std::string error_;
  long resets_ = 0;
  long long last_command_ = 0;
  long frames_ = 0;
  bool pushing_ = false;
  Command push_;
  PushForce push_force_;
  Eigen::VectorXd push_torque_;  // Je^T F of push_force_, or zero
  std::vector<double> values_;  // scratch: plot values
  std::vector<std::vector<double>> samples_;  // plot samples since the last frame
  std::vector<Eigen::Vector3d> markers_;
  long steps_since_sample_ = 0;
};

}  // namespace opspace::live
