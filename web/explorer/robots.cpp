#include "robots.hpp"

#include <stdexcept>

#include "opspace/scenarios/p1b.hpp"
#include "opspace/scenarios/p2.hpp"
#include "opspace/scenarios/p4.hpp"
#include "opspace/model/urdf.hpp"

namespace opspace::explore {

namespace {

namespace sc = opspace::scenarios;

Robot make(std::string key, std::string title, std::string caption, const char* urdf, const char* tip_link,
           const Eigen::Vector3d& point, Eigen::VectorXd q0, int self_joint) {
  Robot r;
  r.key = std::move(key);
  r.title = std::move(title);
  r.caption = std::move(caption);
  r.model = load_urdf(robot_path(urdf));
  r.tip_link = tip_link;
  r.tip.frame = r.model.frame_id(tip_link);
  r.tip.point = point;
  r.model.check_joint_vector(q0, "explorer q0");
  r.q0 = std::move(q0);
  r.self_joint = self_joint;
  return r;
}

}  // namespace

std::vector<Robot> course_robots() {
  std::vector<Robot> robots;
  // Problem 1a: x_ee = d1 + d2, so Jv has one non-zero row: the tip moves along X0 only, and
  // Y0, Z0 are singular everywhere (by design, not by configuration).
  robots.push_back(make("pp", "PP robot (problem 1a)",
                        "Two prismatic joints along X0, m1 = 10 kg and m2 = 5 kg, task x_ee = d1 + d2. Move the tip "
                        "along X0: J+ splits the motion equally over d1 and d2, Jbar = A^-1 J^T (J A^-1 J^T)^-1 = [0 1]^T "
                        "moves only the light link (1a-vi). Y0 and Z0 are singular at every configuration: the robot "
                        "cannot move there at all.",
                        "pp.urdf", "end-effector", Eigen::Vector3d::Zero(), Eigen::Vector2d::Zero(), 0));
  robots.push_back(make("puma", "PUMA 560 (problem 1b)",
                        "Six joints for a three-dimensional positioning task: a three-dimensional null space. The "
                        "self-motion slider asks for problem 1b's null-space motion of q2 through I - J+ J and through "
                        "I - Jbar J: both hold the tip still here, at the velocity level, but they answer the same "
                        "request with different motions. Through torques (1b PART2 and PART3) only Jbar's projector "
                        "keeps the tip still.",
                        sc::p1b::kRobotFile, sc::p1b::kTipLink, sc::p1b::tip_point(), sc::p1b::initial_q(), 1));
  robots.push_back(make("iiwa", "KUKA iiwa (problems 2 and 3)",
                        "Seven joints; the operational point is link7's origin. Its position task leaves four "
                        "degrees of freedom: joint 3 turns the elbow about the shoulder-wrist line.",
                        sc::p2::kRobotFile, sc::p2::kTipLink, Eigen::Vector3d::Zero(), sc::p2::initial_q(), 2));
  robots.push_back(make("rrr", "3R elbow arm (problem 4)",
                        "Problem 4's configuration theta = (0, 90 deg, 0): the arm stands straight up. Z0 is a Type I "
                        "singular direction (elbow lock: a self-motion that folds the elbow moves the tip down) and "
                        "Y0 a Type II one (overhead lock: joint 1 must first turn the singular direction away).",
                        sc::p4::kRobotFile, sc::p4::kTipLink, sc::p4::tip_point(), sc::p4::singular_q(), 1));
  return robots;
}

Robot course_robot(const std::string& key) {
  for (Robot& r : course_robots()) {
    if (r.key == key) return r;
  }
  throw std::invalid_argument("no robot '" + key + "' in the explorer: pp, puma, iiwa or rrr");
}

}  // namespace opspace::explore
