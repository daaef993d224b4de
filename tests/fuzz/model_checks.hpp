// What a fuzz target requires of a Model that a parser accepted (fuzz-urdf, fuzz-model-text):
// every number one the dynamics and the simulation can use. A finding aborts, which libFuzzer
// records as a crash with its input.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "opspace/model/model.hpp"

namespace fuzz {

/// Reports a finding and aborts, which libFuzzer records as a crash with its input.
inline void require(bool ok, const std::string& what) {
  if (ok) return;
  std::fprintf(stderr, "finding: %s\n", what.c_str());
  std::abort();
}

/// A rigid transform: finite, with a rotation part R^T R = 1 (to rounding).
inline bool finite(const Eigen::Isometry3d& X) {
  return X.matrix().allFinite() && (X.linear().transpose() * X.linear()).isIdentity(1e-9);
}

inline void check_inertia(const opspace::Inertia& in, const std::string& who) {
  require(std::isfinite(in.mass) && in.mass >= 0.0, who + ": mass not finite and >= 0");
  require(in.com.allFinite() && in.inertia.allFinite(), who + ": COM or inertia not finite");
}

inline void check_shape(const opspace::Shape& s, int dof) {
  const std::string who = "shape of link '" + s.link + "'";
  require(s.body >= -1 && s.body < dof, who + ": body index out of range");
  require(finite(s.placement), who + ": placement not a finite rigid transform");
  require(s.box_size.allFinite() && s.box_size.minCoeff() >= 0.0, who + ": box size not finite and >= 0");
  require(std::isfinite(s.radius) && s.radius >= 0.0, who + ": radius not finite and >= 0");
  require(std::isfinite(s.length) && s.length >= 0.0, who + ": length not finite and >= 0");
}

/// Every number of a loaded Model is one the dynamics and the simulation can use.
inline void check_model(const opspace::Model& model) {
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

}  // namespace fuzz
