// The explorer page's data block (page_data.hpp), written with nlohmann-json (page_json.hpp).
#include "page_data.hpp"

#include "explore.hpp"
#include "opspace/model/model_text.hpp"
#include "opspace/visuals/replay.hpp"
#include "page_json.hpp"

namespace opspace::explore {

namespace {

/// The text of `json` for an HTML data block: '<' written \u003c, so that no "</script>" ends
/// the block early (JSON has '<' only inside strings), and bytes that are not UTF-8 replaced
/// (U+FFFD) instead of thrown on.
std::string script_text(const Json& json) {
  std::string out;
  for (const char c : json.dump(-1, ' ', false, Json::error_handler_t::replace)) {
    if (c == '<') {
      out += "\\u003c";
    } else {
      out += c;
    }
  }
  return out;
}

Json robot_data(const Robot& r) {
  replay::Scene scene;
  scene.title = r.title;
  scene.model = r.model;
  scene.t = {0.0};
  scene.q = {r.q0};
  Json joints = Json::array();
  for (const Body& b : r.model.bodies) {
    joints.push_back(Json{{"name", b.joint_name},
                          {"prismatic", b.type == JointType::kPrismatic},
                          {"lower", json_number(b.lower)},
                          {"upper", json_number(b.upper)}});
  }
  Json q0 = Json::array();
  for (Eigen::Index i = 0; i < r.q0.size(); ++i) q0.push_back(json_number(r.q0(i)));
  return Json{{"key", r.key},
              {"title", r.title},
              {"caption", r.caption},
              {"model", write_model_text(r.model)},
              {"tip_link", r.tip_link},
              {"tip_point", {json_number(r.tip.point.x()), json_number(r.tip.point.y()), json_number(r.tip.point.z())}},
              {"joints", std::move(joints)},
              {"q0", std::move(q0)},
              {"self_joint", r.self_joint},
              // The replay's own JSON text (lib/src/visuals/replay.cpp), read back as JSON.
              {"scene", Json::parse(replay::scene_json(scene))}};
}

}  // namespace

std::string robot_json(const Robot& robot) { return script_text(robot_data(robot)); }

std::string page_data_json(const std::vector<Robot>& robots) {
  Json list = Json::array();
  for (const Robot& r : robots) list.push_back(robot_data(r));
  return script_text(Json{{"robots", std::move(list)}});
}

}  // namespace opspace::explore
