#include "robots.hpp"

#include <stdexcept>

#include "opspace/model/catalogue.hpp"

namespace opspace::explore {

namespace {

namespace cat = opspace::catalogue;

/// The catalogue's robot `entry` with what the page says about it, opening at `q0`.
Robot make(const cat::CourseRobot& entry, std::string title, std::string caption, Eigen::VectorXd q0,
           int self_joint) {
  Robot r;
  r.key = entry.key;
  r.title = std::move(title);
  r.caption = std::move(caption);
  r.model = cat::load(entry);
  r.tip_link = entry.tip_link;
  r.tip.frame = r.model.frame_id(entry.tip_link);
  r.tip.point = cat::tip_point(entry);
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
  robots.push_back(make(cat::kPP, "PP robot (problem 1a)",
                        "Two prismatic joints along X0, m1 = 10 kg and m2 = 5 kg, task x_ee = d1 + d2. Move the tip "
                        "along X0: J+ splits the motion equally over d1 and d2, Jbar = A^-1 J^T (J A^-1 J^T)^-1 = [0 1]^T "
                        "moves only the light link (1a-vi). Y0 and Z0 are singular at every configuration: the robot "
                        "cannot move there at all.",
                        Eigen::Vector2d::Zero(), 0));
  robots.push_back(make(cat::kPuma, "PUMA 560 (problem 1b)",
                        "Six joints for a three-dimensional positioning task: a three-dimensional null space. The "
                        "self-motion slider asks for problem 1b's null-space motion of q2 through I - J+ J and through "
                        "I - Jbar J: both hold the tip still here, at the velocity level, but they answer the same "
                        "request with different motions. Through torques (1b PART2 and PART3) only Jbar's projector "
                        "keeps the tip still.",
                        cat::puma_start_q(), 1));
  robots.push_back(make(cat::kIiwa, "KUKA iiwa (problems 2 and 3)",
                        "Seven joints; the operational point is link7's origin. Its position task leaves four "
                        "degrees of freedom: joint 3 turns the elbow about the shoulder-wrist line.",
                        cat::iiwa_start_q(), 2));
  robots.push_back(make(cat::kRRR, "3R elbow arm (problem 4)",
                        "Problem 4's configuration theta = (0, 90 deg, 0): the arm stands straight up. Z0 is a Type I "
                        "singular direction (elbow lock: a self-motion that folds the elbow moves the tip down) and "
                        "Y0 a Type II one (overhead lock: joint 1 must first turn the singular direction away).",
                        cat::rrr_singular_q(), 1));
  return robots;
}

Robot course_robot(const std::string& key) {
  for (Robot& r : course_robots()) {
    if (r.key == key) return r;
  }
  throw std::invalid_argument("no robot '" + key + "' in the explorer: pp, puma, iiwa or rrr");
}

}  // namespace opspace::explore
