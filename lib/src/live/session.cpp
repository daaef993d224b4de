// A live session: commands, steps, frames and the log (live/session.hpp).
#include "opspace/live/session.hpp"

#include <cmath>
#include <iostream>
#include <utility>
#include <nlohmann/json.hpp>

#include "opspace/algorithms/kinematics.hpp"

namespace opspace::live {

namespace {

using Json = nlohmann::ordered_json;

/// Plot samples are kept every this many steps (5 ms at 1 ms): 2000 points per 10 s window.
constexpr long kSampleEvery = 5;

Json num(double v) {
  if (!std::isfinite(v)) return nullptr;  // JSON has no NaN: the page leaves a gap
  return v;
}

Json vec(const Eigen::Vector3d& v) { return Json::array({num(v.x()), num(v.y()), num(v.z())}); }

void pose(Json& out, const Eigen::Isometry3d& X) {
  const Eigen::Quaterniond r(X.rotation());
  const Eigen::Vector3d p = X.translation();
  for (const double v : {p.x(), p.y(), p.z(), r.x(), r.y(), r.z(), r.w()}) out.push_back(num(v));
}

}  // namespace

std::vector<std::string> session_columns(const Lab& lab) {
  std::vector<std::string> columns = lab.csv_columns();
  for (const char* c : {"law", "speed", "push_body", "push_fx", "push_fy", "push_fz", "resets"}) columns.push_back(c);
  for (const Gain& g : lab.info().gains) columns.push_back(g.name);
  return columns;
}

Session::Session(Lab& lab, const std::string& csv_path, const Spring& spring) : lab_(lab), spring_(spring) {
  limits_.laws = static_cast<int>(lab.info().laws.size());
  limits_.gains = lab.info().gains;
  limits_.bodies = lab.simulation().model().dof();
  if (!csv_path.empty()) csv_ = std::make_unique<CsvLog>(csv_path, session_columns(lab));
  reset();
  resets_ = 0;
}

void Session::submit(std::string_view body) {
  Command c = parse_command(body, limits_);
  const std::lock_guard<std::mutex> lock(queue_mutex_);
  queue_.push_back(c);
}

int Session::apply_queued() {
  std::vector<Command> commands;
  {
    const std::lock_guard<std::mutex> lock(queue_mutex_);
    commands.swap(queue_);
  }
  for (const Command& c : commands) apply(c);
  return static_cast<int>(commands.size());
}

void Session::apply(const Command& c) {
  switch (c.kind) {
    case Command::Kind::kPause: paused_ = true; break;
    case Command::Kind::kResume: paused_ = false; break;
    case Command::Kind::kReset: reset(); break;
    case Command::Kind::kSpeed: speed_ = c.value; break;
    case Command::Kind::kLaw:
      law_ = static_cast<int>(c.value);
      lab_.set_law(law_);
      break;
    case Command::Kind::kGain:
      gains_[c.gain] = c.value;
      lab_.set_gain(c.gain, c.value);
      break;
    case Command::Kind::kPush:
      pushing_ = true;
      push_ = c;
      break;
    case Command::Kind::kRelease: release(); break;
  }
  last_command_ = std::max(last_command_, c.id);
}

void Session::reset() {
  lab_.reset();
  const LabInfo& info = lab_.info();
  law_ = info.law;
  gains_.clear();
  for (const Gain& g : info.gains) gains_.push_back(g.value);
  pusher_ = std::make_unique<Pusher>(lab_.simulation().model());
  push_torque_ = Eigen::VectorXd::Zero(lab_.simulation().model().dof());
  error_.clear();
  release();
  samples_.clear();
  steps_since_sample_ = kSampleEvery;  // the first tick is a sample
  ++resets_;
}

void Session::release() {
  pushing_ = false;
  push_force_ = PushForce{};
  push_torque_.setZero();
}

double Session::time() const { return std::as_const(lab_).simulation().time(); }
double Session::dt() const { return std::as_const(lab_).simulation().settings().dt; }

void Session::step(bool advance) {
  if (paused_ || !error_.empty()) return;
  Simulation& sim = lab_.simulation();
  try {
    const Eigen::VectorXd& tau = lab_.tick();
    if (pushing_) {
      push_force_ = pusher_->force(spring_, sim.q(), sim.qdot(), push_.body, push_.point, push_.target);
      sim.push(push_.body, push_force_.force, push_force_.point);
      push_torque_ = pusher_->joint_torque();
    }
    lab_.set_push_torque(push_torque_);
    if (csv_) {
      std::vector<double> row = lab_.csv_row();
      const Eigen::Vector3d& f = push_force_.force;
      for (const double v : {double(law_), speed_, pushing_ ? double(push_.body) : -1.0, f.x(), f.y(), f.z(),
                             double(resets_)}) {
        row.push_back(v);
      }
      row.insert(row.end(), gains_.begin(), gains_.end());
      csv_->row(row);
    }
    if (++steps_since_sample_ >= kSampleEvery) {
      steps_since_sample_ = 0;
      lab_.plot_values(values_);
      std::vector<double> sample{sim.time()};
      sample.insert(sample.end(), values_.begin(), values_.end());
      samples_.push_back(std::move(sample));
    }
    if (advance) sim.step(tau);
  } catch (const std::exception& e) {
    error_ = e.what();
    std::cerr << lab_.info().program << ": the run stopped at t = " << sim.time() << " s: " << error_
              << "\n  (reset it on the page)\n";
  }
}

std::string Session::frame(double rtf) {
  Simulation& sim = lab_.simulation();
  const Model& model = sim.model();
  const LabInfo& info = lab_.info();
  Json poses = Json::array();
  for (int b = 0; b < model.dof(); ++b) pose(poses, sim.body_pose(b));
  Json markers = Json::object();
  lab_.marker_positions(markers_);
  for (std::size_t i = 0; i < info.markers.size() && i < markers_.size(); ++i) markers[info.markers[i].name] = vec(markers_[i]);
  Json samples = Json::array();
  for (const std::vector<double>& s : samples_) {
    Json row = Json::array();
    for (const double v : s) row.push_back(num(v));
    samples.push_back(std::move(row));
  }
  samples_.clear();
  Json gains = Json::object();
  for (std::size_t i = 0; i < info.gains.size(); ++i) gains[info.gains[i].name] = num(gains_[i]);
  Json push = nullptr;
  if (pushing_) {
    push = Json{{"body", push_.body}, {"point", vec(push_force_.point)}, {"target", vec(push_.target)},
                {"force", vec(push_force_.force)}};
  }
  const Json frame{{"frame", ++frames_}, {"t", num(sim.time())}, {"rtf", num(rtf)},  {"speed", num(speed_)},
                   {"paused", paused_},  {"law", law_},          {"gains", gains},    {"poses", poses},
                   {"markers", markers}, {"samples", samples},   {"push", push},      {"error", error_},
                   {"command", last_command_}};
  return frame.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace opspace::live
