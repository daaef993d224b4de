/// @file model/model.hpp
/// The robot description (Model, built once, never changed by algorithms) and the per-call
/// workspace (Data) that the algorithms of kinematics.hpp and dynamics.hpp fill in.
///
/// A Model is a tree of single-DOF joints. Body i is the rigid body moved by joint i (URDF
/// fixed joints are merged into their parent body); its frame is the URDF child-link frame,
/// i.e. the joint frame. Bodies are in topological order: bodies[i].parent < i.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace opspace {

enum class JointType { kRevolute, kPrismatic };

/// Mass properties of a rigid body, expressed in its body frame.
struct Inertia {
  double mass = 0.0;  ///< mass (kg)
  Eigen::Vector3d com = Eigen::Vector3d::Zero();      ///< centre of mass, body frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< rotational inertia about the COM
};

/// A geometric primitive attached to a body (a URDF collision or visual element).
struct Shape {
  enum class Kind { kBox, kCylinder, kSphere };
  Kind kind = Kind::kBox;  ///< which primitive: the members below that apply to it are set
  Eigen::Vector3d box_size = Eigen::Vector3d::Zero();  ///< box: full edge lengths
  double radius = 0.0;                                 ///< cylinder and sphere
  double length = 0.0;                                 ///< cylinder, along its local z
  int body = -1;                                       ///< -1: the fixed base
  Eigen::Isometry3d placement = Eigen::Isometry3d::Identity();  ///< shape frame in body frame
  std::string link;                                    ///< URDF link it was declared on
};

/// One moving joint and the rigid body it carries.
struct Body {
  std::string joint_name;  ///< URDF name of the joint
  std::string link_name;   ///< URDF name of the child link the joint moves
  JointType type = JointType::kRevolute;  ///< revolute (q in rad) or prismatic (q in m)
  int parent = -1;  ///< index of the parent body, -1 for the fixed base
  /// Joint frame in the parent body frame at q = 0 (URDF joint origin, composed with any
  /// fixed joints between the two moving bodies).
  Eigen::Isometry3d joint_placement = Eigen::Isometry3d::Identity();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< unit joint axis, body frame
  Inertia inertia;  ///< includes the links merged in through fixed joints
  double lower = 0.0;               ///< lower position limit (rad or m)
  double upper = 0.0;               ///< upper position limit (rad or m)
  double effort = 0.0;              ///< torque/force limit (N m or N)
  double velocity = 0.0;            ///< speed limit (rad/s or m/s)
  /// Armature: the reflected inertia of the joint's motor, Jm G^2 for a rotor of inertia Jm
  /// behind a gear of ratio G (kg m^2, or kg for a prismatic joint), 0 by default. It adds to
  /// A(q)'s diagonal entry i only (a rotor spinning G times faster than its joint dominates
  /// its own kinetic energy; its coupling with the other joints, of order 1/G, is neglected, as
  /// in the Robotics Toolbox). Read from the URDF extension `<armature>` (docs/model.md), or
  /// set here on a loaded Model before its Data and algorithms use it.
  double armature = 0.0;
};

/// Every URDF link by name, moving or merged, so that a tool frame can serve as a tip.
struct Frame {
  std::string name;  ///< URDF link name
  int body = -1;  ///< -1: attached to the fixed base
  Eigen::Isometry3d placement = Eigen::Isometry3d::Identity();  ///< frame in body frame
};

/// Immutable robot description, built by load_urdf() (urdf.hpp).
struct Model {
  std::string name;    ///< URDF robot name
  std::string source;  ///< file (or label) the model was read from, for error messages
  std::vector<Body> bodies;       ///< moving bodies, parents before children; index = joint index
  std::vector<Frame> frames;      ///< every URDF link, by frame_id()
  std::vector<Shape> collisions;  ///< URDF `<collision>` shapes (the simulation's contact geometry)
  std::vector<Shape> visuals;     ///< URDF `<visual>` shapes (drawn by the replay page)
  Inertia base_inertia;  ///< of the fixed root link (plays no part in the dynamics)
  Eigen::Vector3d gravity = Eigen::Vector3d(0.0, 0.0, -9.81);  ///< base frame, m/s^2

  /// Number of joints (= degrees of freedom = bodies.size()).
  int dof() const { return static_cast<int>(bodies.size()); }
  /// Index in frames of the link `name`; throws std::out_of_range naming it and the model.
  int frame_id(const std::string& name) const;
  /// Index in bodies of the joint `name`; throws std::out_of_range naming it and the model.
  int joint_id(const std::string& name) const;
  /// Throws std::invalid_argument naming `what` and the sizes unless v has dof() entries.
  void check_joint_vector(const Eigen::Ref<const Eigen::VectorXd>& v, const char* what) const;
};

/// A spatial inertia about the base origin O, in the base frame, by its ten numbers: mass m,
/// first moment h = m c (c: centre of mass) and rotational inertia I about O. It stands for the
/// 6x6 matrix [[m 1, -[h]], [[h], I]], which is never formed; the inertia of several bodies is
/// the sum of each of the three.
struct SpatialInertia {
  double m = 0.0;                                 ///< mass (kg)
  Eigen::Vector3d h = Eigen::Vector3d::Zero();    ///< first moment m c (kg m)
  Eigen::Matrix3d I = Eigen::Matrix3d::Zero();    ///< rotational inertia about O (kg m^2)
};

/// Workspace of the algorithms: sized once from a Model, then reused without allocation.
struct Data {
  /// Sizes every member for `model`: the only allocation of the algorithms.
  explicit Data(const Model& model);

  std::vector<Eigen::Isometry3d> body_pose;  ///< oMi: body frames in the base frame
  Eigen::MatrixXd A;        ///< joint-space mass matrix A(q)            (crba)
  Eigen::VectorXd g;        ///< gravity torques g(q)                    (generalized_gravity)
  Eigen::VectorXd b;        ///< Coriolis/centrifugal torques b(q, qdot) (coriolis_centrifugal)
  Eigen::VectorXd tau;      ///< inverse dynamics A qdd + b + g          (rnea)
  Eigen::VectorXd qdd;      ///< forward dynamics A^-1 (tau - b - g)     (forward_dynamics)
  Eigen::MatrixXd A_factor; ///< Cholesky factor L of A = L L^T (lower triangle) (forward_dynamics)

  // Recursion workspace, one entry per body (spatial quantities in the base frame, about its
  // origin O: motion [v_O; w], force [f; n_O]).
  std::vector<Eigen::Matrix<double, 6, 1>> v;  ///< spatial velocity [v_O; w] (m/s, rad/s)
  std::vector<Eigen::Matrix<double, 6, 1>> a;  ///< spatial acceleration (rnea: offset by -gravity)
  std::vector<Eigen::Matrix<double, 6, 1>> f;  ///< spatial force [f; n_O] (N, N m) across the joint (rnea)
  std::vector<Eigen::Matrix<double, 6, 1>> S;  ///< joint motion subspace: spatial velocity per unit qdot
  std::vector<SpatialInertia> Ic;  ///< composite inertia of the body's subtree (crba, generalized_gravity)
};

}  // namespace opspace
