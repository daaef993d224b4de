/// @file simulation/closed_loop.hpp
/// The scaffolding around a controller: checking what it returns, reporting progress,
/// writing a CSV log.
#pragma once

#include <Eigen/Core>
#include <fstream>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace opspace {

/// A controller returned something the simulation cannot apply.
class ControllerError : public std::runtime_error {
 public:
  /// `message` says what the controller returned and when; `time` is that tick's time (s).
  ControllerError(const std::string& message, double time)
      : std::runtime_error(message), time_(time) {}
  double time() const { return time_; }  ///< simulated time (s) of the bad tick

 private:
  double time_;
};

/// Throws ControllerError "<who> returned NaN in tau[i] at t = ... s" (or inf, or a wrong
/// size) unless tau is a finite vector of `dof` torques.
void check_torque(const Eigen::Ref<const Eigen::VectorXd>& tau, Eigen::Index dof, double t,
                  const std::string& who);

/// Prints "label: t = 3.0 / 20.0 s" to `out` every `every` seconds of simulated time, on one
/// line rewritten in place when `out` is a terminal.
class Progress {
 public:
  /// Reports on `out` for a run of `duration` simulated seconds, every `every` seconds.
  Progress(std::ostream& out, std::string label, double duration, double every = 1.0);
  /// Prints "label: t = ... / duration s" when t has passed the next reporting time.
  void update(double t);
  /// Ends the line rewritten in place (on a terminal).
  void finish();

 private:
  std::ostream& out_;
  std::string label_;
  double duration_, every_, next_ = 0.0;
  bool in_place_;
};

/// A CSV file with a header row; rows of numbers at full precision.
class CsvLog {
 public:
  /// Opens `path` (creating its directory); throws std::runtime_error naming it on failure.
  CsvLog(const std::string& path, const std::vector<std::string>& columns);
  /// Appends one row; throws std::invalid_argument unless it has one value per column.
  void row(const std::vector<double>& values);
  const std::string& path() const { return path_; }  ///< the file being written

 private:
  std::string path_;
  std::size_t columns_;
  std::ofstream file_;
};

}  // namespace opspace
