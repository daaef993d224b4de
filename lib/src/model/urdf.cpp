// URDF loading in three passes:
//  0. Scans of the text: it must be UTF-8 without NUL bytes (TinyXML reads past the end of
//     a cut UTF-8 sequence), and the markup's nesting depth and attributes per element are
//     bounded (TinyXML recurses once per level and compares each new attribute with the
//     element's others: the call stack or quadratic time would pay for them).
//  1. TinyXML (which urdfdom itself depends on) checks what urdfdom does not, or reports
//     without a line number: well-formed XML, joint types, mimic joints, the tree shape
//     (one parent per link, one root, no loop). It also records each link's and joint's line.
//  2. urdfdom parses the checked text; the links are walked from the root into a Model,
//     with every number checked on the way (masses, inertias, limits, shape sizes, and the
//     sums and products of finite numbers that overflow).
// urdfdom's console_bridge messages are captured while it parses, so the user sees only our
// UrdfError (console_bridge's handler is process-global: do not load URDFs from two threads).
#include "opspace/model/urdf.hpp"

#include <tinyxml.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <console_bridge/console.h>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <urdf_parser/urdf_parser.h>

#include "printable.hpp"
#include "inertia_check.hpp"

namespace opspace {

namespace {

using detail::hex;
using detail::printable;

/// "<source>:<line>: <cause>", or "<source>: <cause>" when the line is unknown (line <= 0).
[[noreturn]] void fail(const std::string& source, int line, const std::string& cause) {
  throw UrdfError(source + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + printable(cause));
}

/// Length of the well-formed UTF-8 character at xml[i] (Unicode, table 3-7: a lead byte, a
/// second byte in a range the lead sets, then bytes in 0x80-0xbf); 0 if it is malformed.
std::size_t utf8_length(const std::string& xml, std::size_t i) {
  const auto at = [&](std::size_t k) -> unsigned { return k < xml.size() ? static_cast<unsigned char>(xml[k]) : 0u; };
  const unsigned c = at(i);
  if (c < 0x80) return 1;
  std::size_t length = 0;
  unsigned low = 0x80, high = 0xbf;
  if (c >= 0xc2 && c <= 0xdf) {
    length = 2;
  } else if (c >= 0xe0 && c <= 0xef) {
    length = 3;
    low = c == 0xe0 ? 0xa0 : low;   // no overlong forms
    high = c == 0xed ? 0x9f : high;  // no surrogates
  } else if (c >= 0xf0 && c <= 0xf4) {
    length = 4;
    low = c == 0xf0 ? 0x90 : low;
    high = c == 0xf4 ? 0x8f : high;  // nothing above U+10FFFF
  } else {
    return 0;
  }
  if (at(i + 1) < low || at(i + 1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (at(i + k) < 0x80 || at(i + k) > 0xbf) return 0;
  }
  return length;
}

/// Pass 0, first: the text is UTF-8 (what both parsers read it as) without NUL bytes (where
/// they would stop reading). TinyXML steps over a character by the length its first byte
/// announces, so a sequence cut short by the end of the text made it read past the end (found
/// by fuzz-urdf under AddressSanitizer).
void check_encoding(const std::string& xml, const std::string& source) {
  int line = 1;
  for (std::size_t i = 0; i < xml.size();) {
    const char c = xml[i];
    const std::size_t length = c == '\0' ? 0 : utf8_length(xml, i);
    if (length == 0) {
      fail(source, line, c == '\0' ? "a NUL byte: a URDF is text"
                                   : "malformed UTF-8 at byte 0x" + hex(c) + " (a URDF is UTF-8 text)");
    }
    if (c == '\n' || (c == '\r' && (i + 1 == xml.size() || xml[i + 1] != '\n'))) ++line;
    i += length;
  }
}

/// Pass 0's bounds: a URDF nests about 5 elements deep and gives one at most 6 attributes.
constexpr int kMaxDepth = 100;
constexpr int kMaxAttributes = 100;

/// Pass 0: walks the tags (comments, CDATA sections, declarations skipped; quoted attribute
/// values honoured) counting lines as TinyXML does ("\r\n", "\r" and "\n" end one), and
/// refuses an element nested deeper than kMaxDepth or with more than kMaxAttributes.
void check_markup(const std::string& xml, const std::string& source) {
  const std::size_t n = xml.size();
  std::size_t i = 0;
  int line = 1, depth = 0;
  const auto skip_to = [&](std::size_t end) {  // moves i to end (at most n), counting lines
    end = std::min(end, n);
    for (; i < end; ++i) {
      if (xml[i] == '\n' || (xml[i] == '\r' && (i + 1 == n || xml[i + 1] != '\n'))) ++line;
    }
  };
  const auto past = [&](const char* token, std::size_t from) {  // the end of the next `token`
    const std::size_t at = xml.find(token, from);
    return at == std::string::npos ? n : at + std::strlen(token);
  };
  while (i < n) {
    skip_to(xml.find('<', i));
    if (i >= n) break;
    if (xml.compare(i, 4, "<!--") == 0) {
      skip_to(past("-->", i + 4));
    } else if (xml.compare(i, 9, "<![CDATA[") == 0) {
      skip_to(past("]]>", i + 9));
    } else if (i + 1 < n && (xml[i + 1] == '?' || xml[i + 1] == '!' || xml[i + 1] == '/')) {
      if (xml[i + 1] == '/') depth = std::max(0, depth - 1);
      skip_to(past(">", i + 1));
    } else {  // a start tag, up to its '>' outside quotes
      const int row = line;
      int attributes = 0;
      std::size_t k = i + 1;
      for (; k < n && xml[k] != '>'; ++k) {
        if (xml[k] == '"' || xml[k] == '\'') {
          k = std::min(xml.find(xml[k], k + 1), n - 1);
        } else if (xml[k] == '=' && ++attributes > kMaxAttributes) {
          fail(source, row, "an element with more than " + std::to_string(kMaxAttributes) +
                                " attributes (a URDF element has at most 6)");
        }
      }
      if (k < n && xml[k - 1] != '/' && ++depth > kMaxDepth) {
        fail(source, row, "elements nested more than " + std::to_string(kMaxDepth) +
                              " deep (a URDF nests about 5)");
      }
      skip_to(k + 1);
    }
  }
}

/// Line of each link and joint element, from pass 1.
struct Lines {
  std::map<std::string, int> link, joint;
};

std::string attribute(const TiXmlElement* e, const char* name) {
  const char* value = e ? e->Attribute(name) : nullptr;
  return value ? value : "";
}

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

/// Collects console_bridge messages (urdfdom's) instead of printing them.
class CapturedLog : public console_bridge::OutputHandler {
 public:
  CapturedLog() { console_bridge::useOutputHandler(this); }
  ~CapturedLog() override { console_bridge::restorePreviousOutputHandler(); }
  CapturedLog(const CapturedLog&) = delete;
  CapturedLog& operator=(const CapturedLog&) = delete;
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) errors += (errors.empty() ? "" : "; ") + text;
  }
  std::string errors;
};

Eigen::Isometry3d to_isometry(const urdf::Pose& pose) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
                   .normalized()
                   .toRotationMatrix();
  X.translation() << pose.position.x, pose.position.y, pose.position.z;
  return X;
}

/// m = m1 + m2, c = (m1 c1 + m2 c2) / m,  I = sum_k I_k + m_k (|d_k|^2 1 - d_k d_k^T), d_k = c_k - c.
Inertia combine(const Inertia& a, const Inertia& b) {
  Inertia r;
  r.mass = a.mass + b.mass;
  r.com = r.mass > 0.0 ? Eigen::Vector3d((a.mass * a.com + b.mass * b.com) / r.mass) : a.com;
  r.inertia = a.inertia + b.inertia;
  for (const Inertia* k : {&a, &b}) {
    const Eigen::Vector3d d = k->com - r.com;
    r.inertia += k->mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  return r;
}

bool finite(const Inertia& in) { return std::isfinite(in.mass) && in.com.allFinite() && in.inertia.allFinite(); }

/// Builds the Model from urdfdom's tree, merging fixed-joint children into their parent body.
class Builder {
 public:
  Builder(Model& model, const urdf::ModelInterface& tree, const Lines& lines)
      : model_(model), tree_(tree), lines_(lines) {}

  /// Adds `root` and every link below it, depth first with each link's joints in file order
  /// (the order of q). A stack, not recursion: a long chain of links must not exhaust the
  /// call stack.
  void add_tree(const urdf::Link& root) {
    struct Item {
      const urdf::Joint* joint;  // into `link`; null for the root
      const urdf::Link* link;
      int body;                  // the parent's body (-1: the base)
      Eigen::Isometry3d X;       // the parent link's frame in that body
    };
    std::vector<Item> stack{{nullptr, &root, -1, Eigen::Isometry3d::Identity()}};
    while (!stack.empty()) {
      Item item = stack.back();
      stack.pop_back();
      if (item.joint) add_joint(*item.joint, *item.link, item.body, item.X);
      add_link(*item.link, item.body, item.X);
      std::vector<urdf::JointSharedPtr> joints = item.link->child_joints;
      std::sort(joints.begin(), joints.end(), [&](const auto& a, const auto& b) {
        return lines_.joint.at(a->name) > lines_.joint.at(b->name);  // the first on top
      });
      for (const auto& joint : joints) {
        stack.push_back({joint.get(), tree_.getLink(joint->child_link_name).get(), item.body, item.X});
      }
    }
  }

 private:
  /// Adds `link`, whose frame is X in body `body` (-1: the base): its frame, mass and shapes.
  void add_link(const urdf::Link& link, int body, const Eigen::Isometry3d& X) {
    model_.frames.push_back(Frame{link.name, body, X});
    Inertia& target = body < 0 ? model_.base_inertia : model_.bodies[body].inertia;
    target = combine(target, link_inertia(link, X));
    if (!finite(target)) {
      fail(model_.source, lines_.link.at(link.name),
           "link '" + link.name + "' has mass properties that overflow (are not finite) once merged into its body");
    }
    for (const auto& c : link.collision_array) add_shape(c->geometry, c->origin, link.name, body, X, model_.collisions);
    for (const auto& v : link.visual_array) add_shape(v->geometry, v->origin, link.name, body, X, model_.visuals);
  }

  /// For the link `child` of `joint`, whose parent link's frame is X in body `body`: a moving
  /// joint adds a body (then the child's frame is the identity in it); a fixed one composes X.
  void add_joint(const urdf::Joint& joint, const urdf::Link& child, int& body, Eigen::Isometry3d& X) {
    const int row = lines_.joint.at(joint.name);
    const Eigen::Isometry3d Xj = X * to_isometry(joint.parent_to_joint_origin_transform);
    if (!Xj.matrix().allFinite()) {
      fail(model_.source, row, "joint '" + joint.name + "' has a placement that overflows (is not finite): "
                               "its origin, or those of the fixed joints above it, are too large");
    }
    if (joint.type == urdf::Joint::FIXED) {
      X = Xj;
      return;
    }
    Body b;
    b.joint_name = joint.name;
    b.link_name = child.name;
    b.type = joint.type == urdf::Joint::PRISMATIC ? JointType::kPrismatic : JointType::kRevolute;
    b.parent = body;
    b.joint_placement = Xj;
    const Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
    // Eigen's stable norm scales first: the squares of (0, 1e308, 0) overflow, and axis / inf
    // would have been a zero axis (found by fuzz-urdf).
    if (axis.stableNorm() < 1e-9) fail(model_.source, row, "joint '" + joint.name + "' has a zero axis");
    b.axis = axis.stableNormalized();
    constexpr double kInf = std::numeric_limits<double>::infinity();
    b.lower = -kInf;
    b.upper = kInf;
    if (joint.limits) {
      const urdf::JointLimits& limits = *joint.limits;
      if (joint.type != urdf::Joint::CONTINUOUS) {
        if (!(limits.lower <= limits.upper)) {
          fail(model_.source, row, "joint '" + joint.name + "' has its lower limit " + number(limits.lower) +
                                       " above its upper limit " + number(limits.upper));
        }
        b.lower = limits.lower;
        b.upper = limits.upper;
      }
      // 0 is allowed: no effort limit (the simulation clamps only to a positive one).
      if (!(limits.effort >= 0.0) || !(limits.velocity >= 0.0)) {
        fail(model_.source, row, "joint '" + joint.name + "' has effort " + number(limits.effort) + " and velocity " +
                                     number(limits.velocity) + "; both limits must be >= 0");
      }
      b.effort = limits.effort;
      b.velocity = limits.velocity;
    }
    model_.bodies.push_back(b);
    body = model_.dof() - 1;
    X = Eigen::Isometry3d::Identity();
  }

  static std::string number(double value) {
    std::ostringstream s;
    s << value;
    return s.str();
  }

  /// The link's inertial, checked, re-expressed in the body frame (link frame = X in it):
  /// c = X c_link, I = R I_link R^T (R: rotation of the inertial frame into the body frame).
  Inertia link_inertia(const urdf::Link& link, const Eigen::Isometry3d& X) const {
    Inertia r;
    if (!link.inertial) return r;
    const urdf::Inertial& in = *link.inertial;
    const int row = lines_.link.at(link.name);
    if (!(in.mass >= 0.0)) {
      std::ostringstream s;
      s << "link '" << link.name << "' has mass " << in.mass << " kg; a mass must be >= 0";
      fail(model_.source, row, s.str());
    }
    Eigen::Matrix3d I;
    I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
    const std::string defect = detail::inertia_defect(I);
    if (!defect.empty()) fail(model_.source, row, "link '" + link.name + "' has an inertia that is " + defect);
    const Eigen::Isometry3d Xc = X * to_isometry(in.origin);
    r.mass = in.mass;
    r.com = Xc.translation();
    r.inertia = Xc.linear() * I * Xc.linear().transpose();
    return r;
  }

  /// A collision or visual shape of `link`: its sizes must be >= 0, its placement finite.
  void add_shape(const urdf::GeometrySharedPtr& geometry, const urdf::Pose& origin, const std::string& link,
                 int body, const Eigen::Isometry3d& X, std::vector<Shape>& out) const {
    if (!geometry) return;
    Shape s;
    std::string what;
    switch (geometry->type) {
      case urdf::Geometry::BOX: {
        const auto& box = static_cast<const urdf::Box&>(*geometry);
        s.kind = Shape::Kind::kBox;
        s.box_size << box.dim.x, box.dim.y, box.dim.z;
        what = "a box of size " + number(box.dim.x) + " " + number(box.dim.y) + " " + number(box.dim.z);
        break;
      }
      case urdf::Geometry::CYLINDER: {
        const auto& cylinder = static_cast<const urdf::Cylinder&>(*geometry);
        s.kind = Shape::Kind::kCylinder;
        s.radius = cylinder.radius;
        s.length = cylinder.length;
        what = "a cylinder of radius " + number(s.radius) + " and length " + number(s.length);
        break;
      }
      case urdf::Geometry::SPHERE:
        s.kind = Shape::Kind::kSphere;
        s.radius = static_cast<const urdf::Sphere&>(*geometry).radius;
        what = "a sphere of radius " + number(s.radius);
        break;
      default:
        return;  // meshes are not drawn nor collided with
    }
    const int row = lines_.link.at(link);
    if (!(s.box_size.minCoeff() >= 0.0 && s.radius >= 0.0 && s.length >= 0.0)) {
      fail(model_.source, row, "link '" + link + "' has " + what + ": sizes must be >= 0");
    }
    s.body = body;
    s.placement = X * to_isometry(origin);
    if (!s.placement.matrix().allFinite()) {
      fail(model_.source, row, "link '" + link + "' has " + what + " whose placement overflows (is not finite)");
    }
    s.link = link;
    out.push_back(s);
  }

  Model& model_;
  const urdf::ModelInterface& tree_;
  const Lines& lines_;
};

}  // namespace

Model parse_urdf(const std::string& xml, const std::string& source) {
  check_encoding(xml, source);
  check_markup(xml, source);
  const Lines lines = check_structure(xml, source);
  urdf::ModelInterfaceSharedPtr tree;
  std::string errors;
  {
    CapturedLog log;
    try {
      tree = urdf::parseURDF(xml);
    } catch (const std::exception& e) {
      log.errors += e.what();
    }
    errors = log.errors;
  }
  if (!tree) {
    fail(source, line_named_in(errors, lines),
         "urdfdom rejected the file: " + (errors.empty() ? "no reason given" : errors));
  }

  Model model;
  model.name = tree->getName();
  model.source = source;
  Builder(model, *tree, lines).add_tree(*tree->getRoot());
  return model;
}

Model load_urdf(const std::string& path) {
  // The largest robots' URDF files are under 1 MB (meshes live in files of their own): the
  // cap keeps a wrong path (/dev/zero, a FIFO, a log) from filling the memory.
  constexpr std::size_t kMaxBytes = std::size_t{16} << 20;
  std::ifstream file(path, std::ios::binary);
  if (!file) fail(path, 0, std::string("cannot open the file (") + std::strerror(errno) + ")");
  std::string text;
  char chunk[1 << 16];
  while (file.read(chunk, sizeof chunk) || file.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(file.gcount()));
    if (text.size() > kMaxBytes) fail(path, 0, "larger than 16 MB: not a URDF (meshes live in files of their own)");
  }
  if (file.bad()) fail(path, 0, std::string("cannot read the file (") + std::strerror(errno) + ")");
  return parse_urdf(text, path);
}

std::string robot_path(const std::string& file_name) { return std::string(OPSPACE_ROBOTS_DIR) + "/" + file_name; }

}  // namespace opspace
