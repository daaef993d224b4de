// Pass 1 of the URDF loader (urdf.cpp), with TinyXML (which urdfdom itself depends on): what
// urdfdom does not check, or reports without a line number: well-formed XML, joint types, mimic
// joints, the tree shape (one parent per link, one root, no loop), and opspace's <armature>
// extension (which urdfdom ignores). It records each link's and
// joint's line, by which a later message names its line: pass 2's, and urdfdom's, whose joint or
// link line_named_in finds.
#include <tinyxml.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "urdf_passes.hpp"

namespace opspace::urdf_passes {

namespace {

std::string attribute(const TiXmlElement* e, const char* name) {
  const char* value = e ? e->Attribute(name) : nullptr;
  return value ? value : "";
}

/// The attribute `name` of the `<armature>` of joint `joint` as a finite number, >= 0 unless
/// `signed_ok` (the whole text a number: strtod alone would take "1e" or "2kg").
double armature_number(const TiXmlElement* e, const char* name, const std::string& joint,
                       const std::string& source, bool signed_ok = false) {
  const std::string text = attribute(e, name);
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v) ||
      (v < 0.0 && !signed_ok)) {
    fail(source, e->Row(), "joint '" + joint + "' has <armature " + name + "=\"" + text +
                               "\">: expected a finite number" + (signed_ok ? "" : " >= 0"));
  }
  return v;
}

/// opspace's extension for a motor's reflected inertia, one per moving joint at most:
/// `<armature value="Jm G^2"/>`, or `<armature rotor_inertia="Jm" gear_ratio="G"/>` (value
/// Jm G^2, the Robotics Toolbox's parameters as published; the sign of G is its direction).
double read_armature(const TiXmlElement* joint, const std::string& name, const std::string& type,
                     const std::string& source) {
  const TiXmlElement* e = joint->FirstChildElement("armature");
  if (e == nullptr) return 0.0;
  if (e->NextSiblingElement("armature")) {
    fail(source, e->NextSiblingElement("armature")->Row(), "joint '" + name + "' has a second <armature>");
  }
  if (type == "fixed") fail(source, e->Row(), "joint '" + name + "' is fixed: an <armature> needs a moving joint");
  const bool by_value = e->Attribute("value") != nullptr;
  const bool by_motor = e->Attribute("rotor_inertia") != nullptr || e->Attribute("gear_ratio") != nullptr;
  if (by_value == by_motor) {
    fail(source, e->Row(), "joint '" + name + "' has an <armature> with " +
                               (by_value ? "both value and rotor_inertia/gear_ratio" : "no value") +
                               ": give value=\"Jm G^2\", or rotor_inertia=\"Jm\" and gear_ratio=\"G\"");
  }
  if (by_value) return armature_number(e, "value", name, source);
  const double jm = armature_number(e, "rotor_inertia", name, source);
  const double ratio = armature_number(e, "gear_ratio", name, source, true);
  const double value = jm * ratio * ratio;
  if (!std::isfinite(value)) fail(source, e->Row(), "joint '" + name + "' has an armature Jm G^2 that overflows");
  return value;
}

}  // namespace

/// Pass 1: XML well-formedness, supported joints, tree shape. Returns the element lines.
Lines check_structure(const std::string& xml, const std::string& source) {
  TiXmlDocument doc;
  doc.Parse(xml.c_str(), nullptr, TIXML_ENCODING_UTF8);
  if (doc.Error()) fail(source, doc.ErrorRow(), std::string("malformed XML: ") + doc.ErrorDesc());
  const TiXmlElement* robot = doc.RootElement();
  if (robot == nullptr || robot->ValueStr() != "robot") {
    fail(source, robot ? robot->Row() : 0, "the document element must be <robot>");
  }
  if (attribute(robot, "name").empty()) fail(source, robot->Row(), "the <robot> has no name");
  Lines lines;
  for (const TiXmlElement* e = robot->FirstChildElement("link"); e; e = e->NextSiblingElement("link")) {
    const std::string name = attribute(e, "name");
    if (name.empty()) fail(source, e->Row(), "a <link> has no name");
    if (!lines.link.emplace(name, e->Row()).second) {
      fail(source, e->Row(), "link '" + name + "' is declared twice (first at line " +
                                 std::to_string(lines.link[name]) + ")");
    }
  }
  if (lines.link.empty()) fail(source, robot->Row(), "the robot has no <link>");

  static const std::set<std::string> kSupported{"revolute", "continuous", "prismatic", "fixed"};
  std::map<std::string, std::string> parent_joint;  // child link -> joint
  std::multimap<std::string, std::string> children;  // parent link -> child links
  for (const TiXmlElement* e = robot->FirstChildElement("joint"); e; e = e->NextSiblingElement("joint")) {
    const std::string name = attribute(e, "name");
    const int row = e->Row();
    if (name.empty()) fail(source, row, "a <joint> has no name");
    if (!lines.joint.emplace(name, row).second) fail(source, row, "joint '" + name + "' is declared twice");
    const std::string type = attribute(e, "type");
    if (type == "floating" || type == "planar") {
      fail(source, row, "joint '" + name + "' is " + type +
                            ": not supported (a fixed-base tree of revolute, continuous, "
                            "prismatic and fixed joints only)");
    }
    if (kSupported.count(type) == 0) {
      fail(source, row, "joint '" + name + "' has unknown type '" + type +
                            "' (expected revolute, continuous, prismatic or fixed)");
    }
    if (const TiXmlElement* mimic = e->FirstChildElement("mimic")) {
      fail(source, mimic->Row(), "joint '" + name + "' mimics joint '" + attribute(mimic, "joint") +
                                     "': mimic joints are not supported");
    }
    if (const double armature = read_armature(e, name, type, source); armature != 0.0) lines.armature[name] = armature;
    const std::string parent = attribute(e->FirstChildElement("parent"), "link");
    const std::string child = attribute(e->FirstChildElement("child"), "link");
    for (const std::string* link : {&parent, &child}) {
      if (lines.link.count(*link) == 0) {
        fail(source, row, "joint '" + name + "' refers to link '" + *link + "', which is not declared");
      }
    }
    const auto [it, inserted] = parent_joint.emplace(child, name);
    if (!inserted) {
      fail(source, row, "link '" + child + "' is the child of both joint '" + it->second +
                            "' and joint '" + name + "': a loop (URDF describes a tree)");
    }
    children.emplace(parent, child);
  }

  // Exactly one root: a link that no joint has as its child.
  std::string root;
  for (const auto& [link, row] : lines.link) {
    if (parent_joint.count(link)) continue;
    if (!root.empty()) {
      const int first = std::min(row, lines.link[root]), second = std::max(row, lines.link[root]);
      fail(source, second, "second root link: links '" + root + "' and '" + link +
                               "' are both without a parent joint (the first root is at line " +
                               std::to_string(first) + ")");
    }
    root = link;
  }
  if (root.empty()) fail(source, robot->Row(), "no root link: every link has a parent joint, so the joints form a loop");

  // With one root and one parent per link, the links form a tree iff all are reachable.
  std::set<std::string> reached{root};
  std::vector<std::string> stack{root};
  while (!stack.empty()) {
    const std::string link = stack.back();
    stack.pop_back();
    const auto range = children.equal_range(link);
    for (auto it = range.first; it != range.second; ++it) {
      if (reached.insert(it->second).second) stack.push_back(it->second);
    }
  }
  for (const auto& [link, row] : lines.link) {
    if (reached.count(link) == 0) {
      fail(source, row, "link '" + link + "' cannot be reached from the root '" + root +
                            "': its joints form a loop");
    }
  }
  return lines;
}

/// The line of the first joint or link that urdfdom's messages name ("Joint [j1] is of type
/// REVOLUTE but...", "Could not parse inertial element for Link [arm]"); 0 if none is named.
int line_named_in(const std::string& errors, const Lines& lines) {
  std::string lower = errors;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  std::size_t first = std::string::npos;
  int row = 0;
  for (const auto& [word, table] : {std::pair{"joint [", &lines.joint}, std::pair{"link [", &lines.link}}) {
    const std::size_t at = lower.find(word);
    if (at >= first) continue;
    const std::size_t begin = at + std::strlen(word), end = errors.find(']', begin);
    if (end == std::string::npos) continue;
    const auto it = table->find(errors.substr(begin, end - begin));
    if (it != table->end()) {
      first = at;
      row = it->second;
    }
  }
  return row;
}

}  // namespace opspace::urdf_passes
