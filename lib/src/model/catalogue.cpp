#include "opspace/model/catalogue.hpp"

#include <stdexcept>

#include "opspace/model/urdf.hpp"

namespace opspace::catalogue {

const CourseRobot& find(std::string_view key) {
  for (const CourseRobot& robot : kCourseRobots) {
    if (key == robot.key) return robot;
  }
  std::string keys;
  for (const CourseRobot& robot : kCourseRobots) keys += std::string(keys.empty() ? "" : ", ") + robot.key;
  throw std::invalid_argument("no course robot '" + std::string(key) + "': " + keys);
}

std::string path(const CourseRobot& robot) { return robot_path(robot.file); }

Model load(const CourseRobot& robot) { return load_urdf(path(robot)); }

}  // namespace opspace::catalogue
