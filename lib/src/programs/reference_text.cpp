#include "opspace/programs/reference_text.hpp"

#include <iomanip>
#include <ios>
#include <ostream>
#include <sstream>

#include "opspace/programs/cli.hpp"

namespace opspace::programs {

std::string exact(double v) {
  std::ostringstream hex;
  hex << std::hexfloat << v;
  return hex.str();
}

std::string exact(const Eigen::Vector3d& v) {
  return "Eigen::Vector3d(" + exact(v(0)) + ", " + exact(v(1)) + ", " + exact(v(2)) + ")";
}

void Assignments::operator()(const char* member, double v) { out_ << "    s." << member << " = " << exact(v) << ";\n"; }
void Assignments::operator()(const char* member, long v) { out_ << "    s." << member << " = " << v << ";\n"; }
void Assignments::operator()(const char* member, int v) { out_ << "    s." << member << " = " << v << ";\n"; }

std::string fixed(double v, int decimals) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << v;
  return s.str();
}

std::string approx(double value, const Unit& unit) { return "~" + show(value, unit); }

std::string max_rms(double max, double rms, const Unit& unit, Show number) {
  return "max " + number(max, unit) + ", RMS " + number(rms, unit);
}

std::string torque(double peak, int joint_index, long clamped, Show number) {
  std::string s = number(peak, kNewtonMetre) + joint(joint_index);
  return s + (clamped ? ", " + number(static_cast<double>(clamped), kJointSteps) + " clamped" : ", none clamped");
}

}  // namespace opspace::programs
