/// @file model/catalogue.hpp
/// The course's robots, each named once: its URDF file in robots/, the point its task
/// controls, and the configurations the problem set starts it at (shared robots.md). The
/// scenarios, the explorer page and the benchmarks read them here.
///
/// It lives in model/ because it knows only files, links and joint vectors: whatever is built
/// on the Model (algorithms, simulation, scenarios, pictures, the explorer, the benchmarks)
/// may read it, and it reads nothing above the Model.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <string_view>

#include "opspace/math/constants.hpp"
#include "opspace/model/model.hpp"

namespace opspace::catalogue {

/// A course robot: its URDF file and its task point, point `tip_offset` (m) of link `tip_link`
/// in that link's frame. A literal type: the entries below are constants, built before any
/// code runs.
struct CourseRobot {
  const char* key;                   ///< short name: pp, puma, iiwa, rrr
  const char* file;                  ///< its URDF in robots/
  const char* tip_link;              ///< the link that carries the task point
  std::array<double, 3> tip_offset;  ///< the task point in tip_link's frame (m)
};

/// Problem 1a: two prismatic joints along X0; the task point is the end-effector's origin.
inline constexpr CourseRobot kPP{"pp", "pp.urdf", "end-effector", {0.0, 0.0, 0.0}};
/// Problem 1b: the PUMA 560; its tip is point (-0.2, 0, 0) of the end-effector.
inline constexpr CourseRobot kPuma{"puma", "puma.urdf", "end-effector", {-0.2, 0.0, 0.0}};
/// Problems 2 and 3: the KUKA iiwa 7; its operational point is link7's origin.
inline constexpr CourseRobot kIiwa{"iiwa", "iiwa7.urdf", "link7", {0.0, 0.0, 0.0}};
/// Problem 4: the 3R elbow arm; its tip is the end-effector's origin, the forearm's far end.
inline constexpr CourseRobot kRRR{"rrr", "rrr.urdf", "end-effector", {0.0, 0.0, 0.0}};

/// Every course robot, in the problems' order.
inline constexpr std::array<CourseRobot, 4> kCourseRobots{kPP, kPuma, kIiwa, kRRR};

/// The entry whose key is `key`; throws std::invalid_argument naming the keys.
const CourseRobot& find(std::string_view key);

/// Its URDF's path in robots/ (robot_path()).
std::string path(const CourseRobot& robot);
/// Its Model, from its URDF (throws as load_urdf does).
Model load(const CourseRobot& robot);
/// Its task point in tip_link's frame.
inline Eigen::Vector3d tip_point(const CourseRobot& robot) {
  return Eigen::Vector3d(robot.tip_offset[0], robot.tip_offset[1], robot.tip_offset[2]);
}

/// Problem 1b's start: q = (90, -22.5, 180, 90, 100, 180) deg, at rest.
inline Eigen::Matrix<double, 6, 1> puma_start_q() {
  return (Eigen::Matrix<double, 6, 1>() << 90.0, -22.5, 180.0, 90.0, 100.0, 180.0).finished() * kDeg;
}

/// Problem 2's start: q = (125.9, 39.2, -49.2, 70.0, -62.4, 80.2, -172.8) deg, at rest (the
/// course writes 187.2 deg for the last joint, beyond its limit: -172.8 is the same angle).
inline Eigen::Matrix<double, 7, 1> iiwa_start_q() {
  return (Eigen::Matrix<double, 7, 1>() << 125.9, 39.2, -49.2, 70.0, -62.4, 80.2, -172.8).finished() * kDeg;
}

/// Problem 4's singular configuration theta = (0, 90 deg, 0): the arm straight up, fully
/// stretched (elbow lock and overhead lock together).
inline Eigen::Vector3d rrr_singular_q() { return Eigen::Vector3d(0.0, 90.0 * kDeg, 0.0); }

}  // namespace opspace::catalogue
