// The explorer page's data block (page_data.hpp).
#include "page_data.hpp"

#include "explore.hpp"
#include "opspace/model_text.hpp"
#include "opspace/replay.hpp"

namespace opspace::explore {

namespace {

/// A JSON string; '<' escaped so that no "</script>" ends the data block early.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '<': out += "\\u003c"; break;
      default: out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
  }
  return out + "\"";
}

}  // namespace

std::string robot_json(const Robot& r) {
  replay::Scene scene;
  scene.title = r.title;
  scene.model = r.model;
  scene.t = {0.0};
  scene.q = {r.q0};
  std::string joints = "[";
  for (const Body& b : r.model.bodies) {
    joints += (joints.size() > 1 ? "," : "") + std::string("{\"name\":") + quoted(b.joint_name) +
              ",\"prismatic\":" + (b.type == JointType::kPrismatic ? "true" : "false") +
              ",\"lower\":" + json_number(b.lower) + ",\"upper\":" + json_number(b.upper) + "}";
  }
  joints += "]";
  std::string q0 = "[";
  for (Eigen::Index i = 0; i < r.q0.size(); ++i) q0 += (i ? "," : "") + json_number(r.q0(i));
  q0 += "]";
  return "{\"key\":" + quoted(r.key) + ",\"title\":" + quoted(r.title) + ",\"caption\":" + quoted(r.caption) +
         ",\"model\":" + quoted(write_model_text(r.model)) + ",\"tip_link\":" + quoted(r.tip_link) +
         ",\"tip_point\":[" + json_number(r.tip.point.x()) + "," + json_number(r.tip.point.y()) + "," +
         json_number(r.tip.point.z()) + "],\"joints\":" + joints + ",\"q0\":" + q0 +
         ",\"self_joint\":" + std::to_string(r.self_joint) + ",\"scene\":" + replay::scene_json(scene) + "}";
}

}  // namespace opspace::explore
