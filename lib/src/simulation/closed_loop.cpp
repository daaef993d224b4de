#include "opspace/simulation/closed_loop.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace opspace {

void check_torque(const Eigen::Ref<const Eigen::VectorXd>& tau, Eigen::Index dof, double t,
                  const std::string& who) {
  std::ostringstream at;
  at << " at t = " << std::fixed << std::setprecision(3) << t << " s";
  if (tau.size() != dof) {
    throw ControllerError(who + " returned " + std::to_string(tau.size()) + " torques instead of " +
                              std::to_string(dof) + at.str(),
                          t);
  }
  for (Eigen::Index i = 0; i < dof; ++i) {
    if (!std::isfinite(tau(i))) {
      throw ControllerError(who + " returned " + (std::isnan(tau(i)) ? "NaN" : "inf") + " in tau[" +
                                std::to_string(i) + "]" + at.str(),
                            t);
    }
  }
}

Progress::Progress(std::ostream& out, std::string label, double duration, double every)
    : out_(out),
      label_(std::move(label)),
      duration_(duration),
      every_(every),
      in_place_((&out == &std::cerr && isatty(STDERR_FILENO)) ||
                (&out == &std::cout && isatty(STDOUT_FILENO))) {}

void Progress::update(double t) {
  if (t + 1e-9 < next_) return;
  next_ += every_;
  out_ << (in_place_ ? "\r" : "") << label_ << ": t = " << std::fixed << std::setprecision(1) << t
       << " / " << duration_ << " s" << (in_place_ ? "" : "\n") << std::flush;
}

void Progress::finish() {
  if (in_place_) out_ << "\n";
  out_ << std::flush;
}

CsvLog::CsvLog(const std::string& path, const std::vector<std::string>& columns)
    : path_(path), columns_(columns.size()) {
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!dir.empty()) std::filesystem::create_directories(dir, ec);
  file_.open(path);
  if (!file_) throw std::runtime_error("cannot write the log " + path);
  for (std::size_t i = 0; i < columns.size(); ++i) file_ << (i ? "," : "") << columns[i];
  file_ << "\n" << std::setprecision(10);
}

void CsvLog::row(const std::vector<double>& values) {
  if (values.size() != columns_) {
    throw std::invalid_argument("CsvLog " + path_ + ": a row of " + std::to_string(values.size()) +
                                " values for " + std::to_string(columns_) + " columns");
  }
  for (std::size_t i = 0; i < values.size(); ++i) file_ << (i ? "," : "") << values[i];
  file_ << "\n";
}

}  // namespace opspace
