// Pass 2 of the URDF loader (urdf.cpp): urdfdom's tree, walked from the root into a Model,
// with every number checked on the way (masses, inertias, limits, shape sizes, and the sums and
// products of finite numbers that overflow). Fixed-joint children merge into their parent body.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <urdf_parser/urdf_parser.h>
#include <vector>

#include "inertia_check.hpp"
#include "urdf_passes.hpp"

namespace opspace::urdf_passes {

namespace {

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
    if (const auto it = lines_.armature.find(joint.name); it != lines_.armature.end()) b.armature = it->second;
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

void build_model(Model& model, const urdf::ModelInterface& tree, const Lines& lines) {
  Builder(model, tree, lines).add_tree(*tree.getRoot());
}

}  // namespace opspace::urdf_passes
