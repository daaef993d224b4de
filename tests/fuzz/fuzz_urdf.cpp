// libFuzzer target: parse_urdf() (lib/src/urdf.cpp: a markup scan, TinyXML, urdfdom, then our
// checks) on arbitrary text. Each input must either give a Model whose every number is usable
// (check_model) or be refused with a UrdfError "fuzz.urdf:<line>: <cause>" or "fuzz.urdf:
// <cause>" (a line of the input, no control character). Any other exception, a sanitizer
// report, a NaN or an infinity in the Model (but the position limits of a continuous joint),
// a hang (-timeout) or a large allocation (-malloc_limit_mb) is a finding.
// Seeds: robots/*.urdf, tests/data/**/*.urdf; dictionary: urdf.dict.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <opspace/urdf.hpp>

namespace {

const char kSource[] = "fuzz.urdf";

/// Reports a finding and aborts, which libFuzzer records as a crash with its input.
void require(bool ok, const std::string& what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz-urdf: %s\n", what.c_str());
  std::abort();
}

/// Lines of `text` as TinyXML and most editors count them: "\r\n", "\r" and "\n" each end one.
long lines(const std::string& text) {
  long n = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))) ++n;
  }
  return n;
}

/// A rigid transform: finite, with a rotation part R^T R = 1 (to rounding).
bool finite(const Eigen::Isometry3d& X) {
  return X.matrix().allFinite() && (X.linear().transpose() * X.linear()).isIdentity(1e-9);
}

void check_inertia(const opspace::Inertia& in, const std::string& who) {
  require(std::isfinite(in.mass) && in.mass >= 0.0, who + ": mass not finite and >= 0");
  require(in.com.allFinite() && in.inertia.allFinite(), who + ": COM or inertia not finite");
}

void check_shape(const opspace::Shape& s, int dof) {
  const std::string who = "shape of link '" + s.link + "'";
  require(s.body >= -1 && s.body < dof, who + ": body index out of range");
  require(finite(s.placement), who + ": placement not a finite rigid transform");
  require(s.box_size.allFinite() && s.box_size.minCoeff() >= 0.0, who + ": box size not finite and >= 0");
  require(std::isfinite(s.radius) && s.radius >= 0.0, who + ": radius not finite and >= 0");
  require(std::isfinite(s.length) && s.length >= 0.0, who + ": length not finite and >= 0");
}

/// Every number of a loaded Model is one the dynamics and the simulation can use.
void check_model(const opspace::Model& model) {
  check_inertia(model.base_inertia, "base");
  for (int i = 0; i < model.dof(); ++i) {
    const opspace::Body& b = model.bodies[static_cast<std::size_t>(i)];
    const std::string who = "joint '" + b.joint_name + "'";
    require(b.parent >= -1 && b.parent < i, who + ": parent not before it");
    require(finite(b.joint_placement), who + ": placement not a finite rigid transform");
    require(b.axis.allFinite() && std::abs(b.axis.norm() - 1.0) < 1e-12, who + ": axis not a unit vector");
    check_inertia(b.inertia, who);
    require(!std::isnan(b.lower) && !std::isnan(b.upper) && b.lower <= b.upper, who + ": limits not ordered");
    require(std::isfinite(b.effort) && b.effort >= 0.0, who + ": effort not finite and >= 0");
    require(std::isfinite(b.velocity) && b.velocity >= 0.0, who + ": velocity not finite and >= 0");
  }
  for (const opspace::Frame& f : model.frames) {
    require(f.body >= -1 && f.body < model.dof(), "frame '" + f.name + "': body index out of range");
    require(finite(f.placement), "frame '" + f.name + "': placement not a finite rigid transform");
  }
  for (const opspace::Shape& s : model.collisions) check_shape(s, model.dof());
  for (const opspace::Shape& s : model.visuals) check_shape(s, model.dof());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string xml(reinterpret_cast<const char*>(data), size);
  try {
    check_model(opspace::parse_urdf(xml, kSource));
  } catch (const opspace::UrdfError& e) {
    // "fuzz.urdf:<line>: <cause>" or "fuzz.urdf: <cause>", with a cause.
    const std::string what = e.what();
    const std::string prefix = std::string(kSource) + ":";
    require(what.rfind(prefix, 0) == 0, "error does not name the file: " + what);
    for (const char c : what) require(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f, "control character in: " + what);
    const std::size_t cause = what.find(": ", prefix.size() - 1);
    require(cause != std::string::npos && what.size() > cause + 2, "error without a cause: " + what);
    if (cause > prefix.size() - 1) {  // a line number: one of the input's lines
      const std::string digits = what.substr(prefix.size(), cause - prefix.size());
      require(digits.find_first_not_of("0123456789") == std::string::npos && digits.size() < 10,
              "line is not a number: " + what);
      const long line = std::stol(digits);
      require(line >= 1 && line <= lines(xml), "line outside the input: " + what);
    }
  }
  return 0;
}
