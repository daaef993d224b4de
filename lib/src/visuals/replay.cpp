#include "opspace/visuals/replay.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "opspace/algorithms/kinematics.hpp"

#ifndef OPSPACE_REPLAY_BUNDLE
#define OPSPACE_REPLAY_BUNDLE ""
#endif

namespace opspace::replay {

namespace fs = std::filesystem;

Marker Marker::point_at(std::string label, std::string color, Track where, double radius) {
  Marker m;
  m.kind = Kind::kPoint;
  m.label = std::move(label);
  m.color = std::move(color);
  m.positions = std::move(where);
  m.radius = radius;
  return m;
}

Marker Marker::trail(std::string label, std::string color, Track where) {
  Marker m;
  m.kind = Kind::kTrail;
  m.label = std::move(label);
  m.color = std::move(color);
  m.positions = std::move(where);
  return m;
}

Marker Marker::arrow(std::string label, std::string color, Track origins, Track vectors, double scale) {
  Marker m;
  m.kind = Kind::kArrow;
  m.label = std::move(label);
  m.color = std::move(color);
  m.positions = std::move(origins);
  m.vectors = std::move(vectors);
  m.scale = scale;
  return m;
}

Marker Marker::plane(std::string label, std::string color, const Eigen::Vector3d& point,
                     const Eigen::Vector3d& normal, double size) {
  Marker m;
  m.kind = Kind::kPlane;
  m.label = std::move(label);
  m.color = std::move(color);
  m.point = point;
  m.normal = normal;
  m.size = size;
  return m;
}

namespace {

/// Link colours by body index (the fixed base is grey).
const char* const kBodyColors[] = {"#e67e22", "#d5d8dc", "#2e86c1", "#d5d8dc", "#e67e22", "#27ae60"};

using Json = nlohmann::ordered_json;  // keys in the order written

/// A number for the page: 6 significant digits (what the viewer draws needs no more, and the page
/// stays small), an integer without a fraction; JSON has no NaN, and the page would not draw one
/// anyway: 0.
Json num(double v) {
  if (!std::isfinite(v)) return 0;
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  const double rounded = std::strtod(text, nullptr);
  if (rounded == std::floor(rounded) && std::abs(rounded) < 1e15) return static_cast<std::int64_t>(rounded);
  return rounded;
}

Json vec(const Eigen::Vector3d& v) { return Json::array({num(v.x()), num(v.y()), num(v.z())}); }

/// [px, py, pz, qx, qy, qz, qw], appended to `out`.
void pose(Json& out, const Eigen::Isometry3d& X) {
  const Eigen::Quaterniond r(X.rotation());
  const Eigen::Vector3d p = X.translation();
  for (const double v : {p.x(), p.y(), p.z(), r.x(), r.y(), r.z(), r.w()}) out.push_back(num(v));
}

Json track(const Track& values, const std::vector<std::size_t>& frames, std::size_t samples, const std::string& what) {
  if (values.size() != 1 && values.size() != samples) {
    throw std::invalid_argument("replay marker '" + what + "': " + std::to_string(values.size()) +
                                " positions for " + std::to_string(samples) + " samples (give one or one per sample)");
  }
  Json out = Json::array();
  if (values.size() == 1) {
    out.push_back(vec(values[0]));
  } else {
    for (const std::size_t k : frames) out.push_back(vec(values[k]));
  }
  return out;
}

const char* kind_name(Shape::Kind kind) {
  switch (kind) {
    case Shape::Kind::kBox: return "box";
    case Shape::Kind::kCylinder: return "cylinder";
    case Shape::Kind::kSphere: return "sphere";
  }
  return "box";
}

const char* kind_name(Marker::Kind kind) {
  switch (kind) {
    case Marker::Kind::kPoint: return "point";
    case Marker::Kind::kTrail: return "trail";
    case Marker::Kind::kArrow: return "arrow";
    case Marker::Kind::kPlane: return "plane";
  }
  return "point";
}

}  // namespace

std::string bundle_path() {
  if (const char* forced = std::getenv("OPSPACE_REPLAY_BUNDLE")) return forced;
  return OPSPACE_REPLAY_BUNDLE;
}

std::vector<std::size_t> frame_indices(const std::vector<double>& t, double fps) {
  std::vector<std::size_t> frames;
  if (t.empty()) return frames;
  const double step = fps > 0.0 ? 1.0 / fps : 0.0;
  frames.push_back(0);
  for (std::size_t i = 1; i + 1 < t.size(); ++i) {
    // Keep a sample once a frame period has passed since the last kept one (1e-9: rounding
    // of logged times that are multiples of the period).
    if (t[i] - t[frames.back()] >= step - 1e-9) frames.push_back(i);
  }
  if (t.size() > 1) frames.push_back(t.size() - 1);
  return frames;
}

std::string scene_json(const Scene& scene) {
  const std::size_t samples = scene.t.size();
  if (scene.q.size() != samples) {
    throw std::invalid_argument("replay scene '" + scene.title + "': " + std::to_string(scene.q.size()) +
                                " joint vectors for " + std::to_string(samples) + " times");
  }
  if (samples == 0) throw std::invalid_argument("replay scene '" + scene.title + "': no samples");
  const Model& model = scene.model;
  const std::vector<std::size_t> frames = frame_indices(scene.t, scene.fps);

  Json shapes = Json::array();
  for (const Shape& shape : model.visuals) {
    Json placement = Json::array();
    pose(placement, shape.placement);
    shapes.push_back(Json{{"kind", kind_name(shape.kind)},
                          {"body", shape.body},
                          {"size", vec(shape.box_size)},
                          {"radius", num(shape.radius)},
                          {"length", num(shape.length)},
                          {"color", shape.body < 0 ? "#7f8c8d" : kBodyColors[shape.body % 6]},
                          {"placement", std::move(placement)}});
  }
  Json times = Json::array();
  for (const std::size_t k : frames) times.push_back(num(scene.t[k]));
  Json poses = Json::array();  // per frame: 7 numbers per body, flat
  Data data(model);
  for (const std::size_t k : frames) {
    forward_kinematics(model, data, scene.q[k]);
    Json frame = Json::array();
    for (int b = 0; b < model.dof(); ++b) pose(frame, data.body_pose[b]);
    poses.push_back(std::move(frame));
  }
  Json markers = Json::array();
  for (const Marker& mk : scene.markers) {
    Json m{{"kind", kind_name(mk.kind)}, {"label", mk.label}, {"color", mk.color},
           {"radius", num(mk.radius)}, {"scale", num(mk.scale)}};
    if (mk.kind == Marker::Kind::kPlane) {
      m["point"] = vec(mk.point);
      m["normal"] = vec(mk.normal);
      m["size"] = num(mk.size);
    } else {
      m["positions"] = track(mk.positions, frames, samples, mk.label);
    }
    if (mk.kind == Marker::Kind::kArrow) {
      m["origins"] = track(mk.positions, frames, samples, mk.label);
      m["vectors"] = track(mk.vectors, frames, samples, mk.label);
    }
    markers.push_back(std::move(m));
  }
  Json hud = Json::array();
  for (const Readout& ro : scene.readouts) {
    if (ro.values.size() != samples) {
      throw std::invalid_argument("replay readout '" + ro.label + "': " + std::to_string(ro.values.size()) +
                                  " values for " + std::to_string(samples) + " samples");
    }
    Json values = Json::array();
    for (const std::size_t k : frames) values.push_back(num(ro.values[k]));
    hud.push_back(Json{{"label", ro.label}, {"values", std::move(values)}});
  }
  const Json scene_data{{"title", scene.title},   {"subtitle", scene.subtitle}, {"robot", model.name},
                        {"bodies", model.dof()},  {"view", vec(scene.view)},    {"shapes", std::move(shapes)},
                        {"t", std::move(times)},  {"poses", std::move(poses)},  {"markers", std::move(markers)},
                        {"hud", std::move(hud)}};
  // '<' written \u003c: no "</script>" can close the data block early (JSON has '<' only inside
  // strings). Bytes that are not UTF-8 are replaced (U+FFFD), never thrown on.
  std::string out;
  for (const char c : scene_data.dump(-1, ' ', false, Json::error_handler_t::replace)) {
    if (c == '<') {
      out += "\\u003c";
    } else {
      out += c;
    }
  }
  return out;
}

Output write(const Scene& scene, const std::string& html_path) {
  Output result;
  const std::string bundle_file = bundle_path();
  std::ifstream in(bundle_file);
  if (bundle_file.empty() || !in) {
    result.skipped = "no 3D replay: the viewer bundle " + (bundle_file.empty() ? std::string("(none configured)") : bundle_file) +
                     " was not built (it needs node and npm at build time: bash scripts/test installs them; "
                     "see docs/visuals.md)";
    return result;
  }
  std::stringstream bundle;
  bundle << in.rdbuf();
  std::string script = bundle.str();
  // The bundle is inlined: a "</script" inside it would end the element early.
  for (std::size_t at = script.find("</script"); at != std::string::npos; at = script.find("</script", at)) {
    script.replace(at, 2, "<\\/");
  }
  const std::string json = scene_json(scene);

  const fs::path path(html_path);
  std::error_code ec;
  if (!path.parent_path().empty()) fs::create_directories(path.parent_path(), ec);
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write the replay page " + html_path);
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<title>opspace replay</title>\n"
      << "<!-- Written by opspace (lib/src/visuals/replay.cpp); viewer: web/src/replay.js with three.js (MIT). -->\n"
      << "</head>\n<body>\n"
      << "<script id=\"opspace-replay-data\" type=\"application/json\">" << json << "</script>\n"
      << "<script>" << script << "</script>\n</body>\n</html>\n";
  if (!out) throw std::runtime_error("cannot write the replay page " + html_path);
  result.page = html_path;
  return result;
}

}  // namespace opspace::replay
