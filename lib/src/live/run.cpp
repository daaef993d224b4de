// A Lab served live and paced to the wall clock (live/run.hpp).
#include "opspace/live/run.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "opspace/live/server.hpp"
#include "opspace/scenarios/watchdog.hpp"
#include "opspace/visuals/replay.hpp"

namespace opspace::live {

namespace {

using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

std::atomic<bool> g_stop{false};
extern "C" void on_signal(int) { g_stop = true; }

// SIGINT and SIGTERM set g_stop while a run is served; the previous handlers come back after.
class StopOnSignal {
 public:
  StopOnSignal() {
    g_stop = false;
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &old_int_);
    sigaction(SIGTERM, &action, &old_term_);
  }
  ~StopOnSignal() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }

 private:
  struct sigaction old_int_ {}, old_term_ {};
};

// The robot's shapes as the replay page describes them (replay::scene_json), at its start.
Json robot_json(Lab& lab) {
  replay::Scene scene;
  scene.model = lab.simulation().model();
  scene.t = {0.0};
  scene.q = {lab.simulation().q()};
  Json j = Json::parse(replay::scene_json(scene));
  return Json{{"robot", j["robot"]}, {"bodies", j["bodies"]}, {"shapes", j["shapes"]}};
}

// The reference's paths, each [x, y, z, x, y, z, ...], or null.
Json ghost_json(const Ghost& ghost) {
  if (ghost.paths.empty()) return nullptr;
  Json paths = Json::array();
  for (const std::vector<Eigen::Vector3d>& path : ghost.paths) {
    Json xyz = Json::array();
    for (const Eigen::Vector3d& p : path) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
    paths.push_back(std::move(xyz));
  }
  return Json{{"label", ghost.label}, {"color", ghost.color}, {"step", ghost.step}, {"paths", paths}};
}

std::string escape_script(std::string text) {
  // Inlined in <script>: "</" would end the element early (JSON and JS both accept "<\/").
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3)) text.insert(at + 1, "\\");
  return text;
}

// Prints the address, publishes the run's first frame (t = 0) and, if `wait`, waits until a page
// opens its event stream, so that the run, and the reference's ghost beside it, start when the
// student sees them. Returns false when a signal ended the wait first.
bool wait_for_page(Server& server, Session& session, bool wait, std::ostream& out) {
  const std::string address = "http://127.0.0.1:" + std::to_string(server.port()) + "/";
  out << "live: " << address << std::endl;
  out << "  open it in a browser (a forwarded port in the devcontainer); Ctrl-C ends the run" << std::endl;
  server.publish(session.frame(0.0));
  if (!wait || server.opened()) return true;
  out << "  waiting for the page at " << address << ": the run starts when it opens" << std::endl;
  while (!g_stop && !server.opened()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  if (g_stop) return false;
  out << "  the page opened: the run starts at t = 0" << std::endl;
  return true;
}

}  // namespace

std::string viewer_path() {
  if (const char* forced = std::getenv("OPSPACE_LIVE_VIEWER")) return forced;
  return OPSPACE_LIVE_VIEWER;
}

std::string page(Lab& lab, double max_force) {
  const LabInfo& info = lab.info();
  Json data = robot_json(lab);
  data["title"] = info.title;
  data["subtitle"] = info.subtitle;
  data["note"] = info.note;
  data["view"] = Json::array({info.view.x(), info.view.y(), info.view.z()});
  data["laws"] = info.laws;
  data["law"] = info.law;
  Json gains = Json::array();
  for (const Gain& g : info.gains) {
    gains.push_back(Json{{"name", g.name}, {"label", g.label}, {"min", g.min}, {"max", g.max}, {"value", g.value}});
  }
  data["gains"] = gains;
  Json plots = Json::array();
  for (const Plot& p : info.plots) {
    Json series = Json::array();
    for (const Series& s : p.series) series.push_back(Json{{"label", s.label}, {"color", s.color}});
    plots.push_back(Json{{"title", p.title}, {"unit", p.unit}, {"series", series}});
  }
  data["plots"] = plots;
  Json markers = Json::array();
  for (const MarkerInfo& m : info.markers) {
    markers.push_back(Json{{"name", m.name}, {"label", m.label}, {"color", m.color}, {"radius", m.radius}});
  }
  data["markers"] = markers;
  data["max_force"] = max_force;
  data["dt"] = lab.simulation().settings().dt;
  data["window"] = info.window;
  data["ghost"] = ghost_json(info.ghost);

  std::ifstream in(viewer_path());
  std::stringstream viewer;
  viewer << in.rdbuf();
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << info.title
       << "</title>\n</head>\n<body>\n";
  if (!in || viewer.str().empty()) {
    html << "<p>The live page's viewer was not built (" << viewer_path()
         << "): the build needs node and npm (bash scripts/setup.sh installs them).</p>\n";
  }
  html << "<script id=\"opspace-live-data\" type=\"application/json\">"
       << escape_script(data.dump(-1, ' ', false, Json::error_handler_t::replace)) << "</script>\n"
       << "<script>" << escape_script(viewer.str()) << "</script>\n</body>\n</html>\n";
  return html.str();
}

void run_unpaced(Session& session, double duration) {
  const long steps = std::lround(duration / session.dt());
  for (long k = 0; k <= steps && session.error().empty(); ++k) session.step(k < steps);
}

LiveReport serve(Lab& lab, const LiveOptions& options, std::ostream& out) {
  Session session(lab, options.csv_path, options.spring);
  Server server(page(lab, options.spring.max_force), options.port, [&session](std::string_view body) { session.submit(body); });
  const StopOnSignal signals;
  LiveReport report;
  if (!wait_for_page(server, session, options.wait_for_page, out)) return report;

  const double dt = session.dt();
  const auto ended = [&options, dt](const Session& s) {
    return options.duration > 0.0 && s.time() >= options.duration - 0.5 * dt;
  };
  const auto frame_period = std::chrono::duration<double>(1.0 / options.frame_rate);
  const Clock::time_point start = Clock::now();
  Clock::time_point last = start, next_frame = start;
  double owed = 0.0;  // simulated seconds the pacing owes the wall clock
  // The real-time factor over the last half second: simulated over wall time.
  Clock::time_point window_start = start;
  double window_sim = session.time(), rtf = 0.0;
  long resets = session.resets();
  scenarios::Watchdog watchdog(options.watchdog, lab.info().program + " --live, the controller");

  while (!g_stop) {
    watchdog.beat(session.time());
    // A command's effect goes out at once, not at the next frame time: the page's latency.
    const bool commanded = session.apply_queued() > 0;
    const Clock::time_point now = Clock::now();
    if (commanded) next_frame = now;
    const double elapsed = std::chrono::duration<double>(now - last).count();
    last = now;
    if (session.resets() != resets) {  // a reset: the clock starts again with the run
      resets = session.resets();
      owed = 0.0;
      window_start = now;
      window_sim = session.time();
    }
    if (!session.paused() && session.error().empty()) {
      owed += elapsed * session.speed();
      if (owed > options.max_lag * session.speed()) {  // too far behind: resynchronise, no burst
        owed = dt;
        ++report.resyncs;
      }
      while (owed >= dt && session.error().empty() && !(ended(session))) {
        session.step();
        owed -= dt;
        ++report.steps;
      }
    } else {
      owed = 0.0;
    }
    const double window = std::chrono::duration<double>(now - window_start).count();
    if (window >= 0.5) {
      rtf = (session.time() - window_sim) / window;
      window_start = now;
      window_sim = session.time();
    }
    if (now >= next_frame) {
      server.publish(session.frame(rtf));
      ++report.frames;
      next_frame += std::chrono::duration_cast<Clock::duration>(frame_period);
      if (next_frame < now) next_frame = now + std::chrono::duration_cast<Clock::duration>(frame_period);
    }
    if (ended(session)) {
      server.publish(session.frame(rtf));
      break;
    }
    // Sleep until the next step is due or the next frame, whichever comes first.
    const double speed = session.paused() ? 1.0 : session.speed();
    const auto step_due = now + std::chrono::duration_cast<Clock::duration>(
                                    std::chrono::duration<double>(std::max(0.0, dt - owed) / speed));
    std::this_thread::sleep_until(std::min(step_due, next_frame));
  }
  report.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return report;
}

}  // namespace opspace::live
