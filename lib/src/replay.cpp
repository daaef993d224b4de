#include "opspace/replay.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "opspace/kinematics.hpp"

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

/// A JSON writer for numbers and plain strings, just what the page needs.
class Json {
 public:
  Json() { out_.precision(6); }
  Json& raw(const char* s) {
    out_ << s;
    return *this;
  }
  Json& num(double v) {
    out_ << (std::isfinite(v) ? v : 0.0);  // JSON has no NaN; the page would not draw one anyway
    return *this;
  }
  Json& str(const std::string& s) {
    out_ << '"';
    for (char c : s) {
      switch (c) {
        case '"': out_ << "\\\""; break;
        case '\\': out_ << "\\\\"; break;
        case '\n': out_ << "\\n"; break;
        case '<': out_ << "\\u003c"; break;  // no "</script>" can close the data block early
        default:
          if (static_cast<unsigned char>(c) < 0x20) {
            out_ << ' ';
          } else {
            out_ << c;
          }
      }
    }
    out_ << '"';
    return *this;
  }
  Json& vec(const Eigen::Vector3d& v) {
    raw("[").num(v.x()).raw(",").num(v.y()).raw(",").num(v.z()).raw("]");
    return *this;
  }
  Json& pose(const Eigen::Isometry3d& X) {
    const Eigen::Quaterniond r(X.rotation());
    const Eigen::Vector3d p = X.translation();
    raw("[").num(p.x()).raw(",").num(p.y()).raw(",").num(p.z()).raw(",").num(r.x()).raw(",").num(r.y());
    raw(",").num(r.z()).raw(",").num(r.w()).raw("]");
    return *this;
  }
  std::string text() const { return out_.str(); }

 private:
  std::ostringstream out_;
};

void track(Json& j, const Track& values, const std::vector<std::size_t>& frames, std::size_t samples,
           const std::string& what) {
  if (values.size() != 1 && values.size() != samples) {
    throw std::invalid_argument("replay marker '" + what + "': " + std::to_string(values.size()) +
                                " positions for " + std::to_string(samples) + " samples (give one or one per sample)");
  }
  j.raw("[");
  if (values.size() == 1) {
    j.vec(values[0]);
  } else {
    for (std::size_t k = 0; k < frames.size(); ++k) j.raw(k ? "," : "").vec(values[frames[k]]);
  }
  j.raw("]");
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

  Json j;
  j.raw("{\"title\":").str(scene.title).raw(",\"subtitle\":").str(scene.subtitle);
  j.raw(",\"robot\":").str(model.name).raw(",\"bodies\":").num(model.dof());
  j.raw(",\"view\":").vec(scene.view);
  j.raw(",\"shapes\":[");
  for (std::size_t s = 0; s < model.visuals.size(); ++s) {
    const Shape& shape = model.visuals[s];
    const char* color = shape.body < 0 ? "#7f8c8d" : kBodyColors[shape.body % 6];
    j.raw(s ? "," : "").raw("{\"kind\":\"").raw(kind_name(shape.kind)).raw("\",\"body\":").num(shape.body);
    j.raw(",\"size\":").vec(shape.box_size).raw(",\"radius\":").num(shape.radius);
    j.raw(",\"length\":").num(shape.length).raw(",\"color\":").str(color);
    j.raw(",\"placement\":").pose(shape.placement).raw("}");
  }
  j.raw("],\"t\":[");
  for (std::size_t k = 0; k < frames.size(); ++k) j.raw(k ? "," : "").num(scene.t[frames[k]]);
  j.raw("],\"poses\":[");
  Data data(model);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    forward_kinematics(model, data, scene.q[frames[k]]);
    j.raw(k ? ",[" : "[");
    for (int b = 0; b < model.dof(); ++b) {
      std::string pose = Json().pose(data.body_pose[b]).text();
      pose = pose.substr(1, pose.size() - 2);  // flat: 7 numbers per body
      j.raw(b ? "," : "").raw(pose.c_str());
    }
    j.raw("]");
  }
  j.raw("],\"markers\":[");
  for (std::size_t m = 0; m < scene.markers.size(); ++m) {
    const Marker& mk = scene.markers[m];
    j.raw(m ? "," : "").raw("{\"kind\":\"").raw(kind_name(mk.kind)).raw("\",\"label\":").str(mk.label);
    j.raw(",\"color\":").str(mk.color).raw(",\"radius\":").num(mk.radius).raw(",\"scale\":").num(mk.scale);
    if (mk.kind == Marker::Kind::kPlane) {
      j.raw(",\"point\":").vec(mk.point).raw(",\"normal\":").vec(mk.normal).raw(",\"size\":").num(mk.size);
    } else {
      j.raw(",\"positions\":");
      track(j, mk.positions, frames, samples, mk.label);
    }
    if (mk.kind == Marker::Kind::kArrow) {
      j.raw(",\"origins\":");
      track(j, mk.positions, frames, samples, mk.label);
      j.raw(",\"vectors\":");
      track(j, mk.vectors, frames, samples, mk.label);
    }
    j.raw("}");
  }
  j.raw("],\"hud\":[");
  for (std::size_t r = 0; r < scene.readouts.size(); ++r) {
    const Readout& ro = scene.readouts[r];
    if (ro.values.size() != samples) {
      throw std::invalid_argument("replay readout '" + ro.label + "': " + std::to_string(ro.values.size()) +
                                  " values for " + std::to_string(samples) + " samples");
    }
    j.raw(r ? "," : "").raw("{\"label\":").str(ro.label).raw(",\"values\":[");
    for (std::size_t k = 0; k < frames.size(); ++k) j.raw(k ? "," : "").num(ro.values[frames[k]]);
    j.raw("]}");
  }
  j.raw("]}");
  return j.text();
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
      << "<!-- Written by opspace (lib/src/replay.cpp); viewer: web/src/replay.js with three.js (MIT). -->\n"
      << "</head>\n<body>\n"
      << "<script id=\"opspace-replay-data\" type=\"application/json\">" << json << "</script>\n"
      << "<script>" << script << "</script>\n</body>\n</html>\n";
  if (!out) throw std::runtime_error("cannot write the replay page " + html_path);
  result.page = html_path;
  return result;
}

}  // namespace opspace::replay
