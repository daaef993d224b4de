// URDF loading in two passes:
//  1. TinyXML (which urdfdom itself depends on) checks what urdfdom does not, or reports
//     without a line number: well-formed XML, joint types, mimic joints, the tree shape
//     (one parent per link, one root, no loop). It also records each link's and joint's line.
//  2. urdfdom parses the checked text; the links are walked from the root into a Model,
//     with mass and inertia checked on the way.
// urdfdom's console_bridge messages are captured while it parses, so the user sees only our
// UrdfError (console_bridge's handler is process-global: do not load URDFs from two threads).
#include "opspace/urdf.hpp"

#include <tinyxml.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cerrno>
#include <console_bridge/console.h>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <urdf_parser/urdf_parser.h>

namespace opspace {

namespace {

/// "<source>:<line>: <cause>", or "<source>: <cause>" when the line is unknown (line <= 0).
[[noreturn]] void fail(const std::string& source, int line, const std::string& cause) {
  throw UrdfError(source + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + cause);
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

/// Builds the Model from urdfdom's tree, merging fixed-joint children into their parent body.
class Builder {
 public:
  Builder(Model& model, const urdf::ModelInterface& tree, const Lines& lines)
      : model_(model), tree_(tree), lines_(lines) {}

  /// Adds `link`, whose frame is X in body `body` (-1: the base), and everything below it.
  void add_link(const urdf::Link& link, int body, const Eigen::Isometry3d& X) {
    model_.frames.push_back(Frame{link.name, body, X});
    Inertia& target = body < 0 ? model_.base_inertia : model_.bodies[body].inertia;
    target = combine(target, link_inertia(link, X));
    for (const auto& c : link.collision_array) add_shape(c->geometry, c->origin, link.name, body, X, model_.collisions);
    for (const auto& v : link.visual_array) add_shape(v->geometry, v->origin, link.name, body, X, model_.visuals);

    std::vector<urdf::JointSharedPtr> joints = link.child_joints;  // in file order, for q's order
    std::sort(joints.begin(), joints.end(), [&](const auto& a, const auto& b) {
      return lines_.joint.at(a->name) < lines_.joint.at(b->name);
    });
    for (const auto& joint : joints) add_joint(*joint, *tree_.getLink(joint->child_link_name), body, X);
  }

 private:
  void add_joint(const urdf::Joint& joint, const urdf::Link& child, int body, const Eigen::Isometry3d& X) {
    const Eigen::Isometry3d Xj = X * to_isometry(joint.parent_to_joint_origin_transform);
    if (joint.type == urdf::Joint::FIXED) {
      add_link(child, body, Xj);
      return;
    }
    Body b;
    b.joint_name = joint.name;
    b.link_name = child.name;
    b.type = joint.type == urdf::Joint::PRISMATIC ? JointType::kPrismatic : JointType::kRevolute;
    b.parent = body;
    b.joint_placement = Xj;
    const Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
    if (axis.norm() < 1e-9) fail(model_.source, lines_.joint.at(joint.name), "joint '" + joint.name + "' has a zero axis");
    b.axis = axis.normalized();
    constexpr double kInf = std::numeric_limits<double>::infinity();
    b.lower = -kInf;
    b.upper = kInf;
    if (joint.limits) {
      if (joint.type != urdf::Joint::CONTINUOUS) {
        b.lower = joint.limits->lower;
        b.upper = joint.limits->upper;
      }
      b.effort = joint.limits->effort;
      b.velocity = joint.limits->velocity;
    }
    model_.bodies.push_back(b);
    add_link(child, model_.dof() - 1, Eigen::Isometry3d::Identity());
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
    // Positive semi-definite: zero stays allowed for massless frames and point masses.
    const Eigen::Vector3d eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I, Eigen::EigenvaluesOnly).eigenvalues();
    if (!I.allFinite() || eig.minCoeff() < -1e-12 * std::max(1.0, eig.cwiseAbs().maxCoeff())) {
      std::ostringstream s;
      s << "link '" << link.name << "' has an inertia that is not positive definite (eigenvalues "
        << eig.transpose() << ")";
      fail(model_.source, row, s.str());
    }
    const Eigen::Isometry3d Xc = X * to_isometry(in.origin);
    r.mass = in.mass;
    r.com = Xc.translation();
    r.inertia = Xc.linear() * I * Xc.linear().transpose();
    return r;
  }

  static void add_shape(const urdf::GeometrySharedPtr& geometry, const urdf::Pose& origin,
                        const std::string& link, int body, const Eigen::Isometry3d& X,
                        std::vector<Shape>& out) {
    if (!geometry) return;
    Shape s;
    switch (geometry->type) {
      case urdf::Geometry::BOX: {
        const auto& box = static_cast<const urdf::Box&>(*geometry);
        s.kind = Shape::Kind::kBox;
        s.box_size << box.dim.x, box.dim.y, box.dim.z;
        break;
      }
      case urdf::Geometry::CYLINDER: {
        const auto& cylinder = static_cast<const urdf::Cylinder&>(*geometry);
        s.kind = Shape::Kind::kCylinder;
        s.radius = cylinder.radius;
        s.length = cylinder.length;
        break;
      }
      case urdf::Geometry::SPHERE:
        s.kind = Shape::Kind::kSphere;
        s.radius = static_cast<const urdf::Sphere&>(*geometry).radius;
        break;
      default:
        return;  // meshes are not drawn nor collided with
    }
    s.body = body;
    s.placement = X * to_isometry(origin);
    s.link = link;
    out.push_back(s);
  }

  Model& model_;
  const urdf::ModelInterface& tree_;
  const Lines& lines_;
};

}  // namespace

Model parse_urdf(const std::string& xml, const std::string& source) {
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
  if (!tree) fail(source, 0, "urdfdom rejected the file: " + (errors.empty() ? "no reason given" : errors));

  Model model;
  model.name = tree->getName();
  model.source = source;
  Builder(model, *tree, lines).add_link(*tree->getRoot(), -1, Eigen::Isometry3d::Identity());
  return model;
}

Model load_urdf(const std::string& path) {
  std::ifstream file(path);
  if (!file) fail(path, 0, std::string("cannot open the file (") + std::strerror(errno) + ")");
  std::ostringstream text;
  text << file.rdbuf();
  return parse_urdf(text.str(), path);
}

std::string robot_path(const std::string& file_name) { return std::string(OPSPACE_ROBOTS_DIR) + "/" + file_name; }

}  // namespace opspace
