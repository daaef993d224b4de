/// @file problems/4/forbidden.hpp
/// Problem 4's answers in the library (grader/trusted/library_answers.hpp): the singularity
/// analysis. A runner that holds one loses the tests it answers. Trusted, but no secret:
/// docs/grader.md lists them for students, and the handout's grader needs them.
#pragma once

#include <string>
#include <vector>

#include "library_answers.hpp"

namespace opspace::grading::forbidden {

inline std::vector<Oracle> p4() {
  const std::vector<std::string> analysis = {
      "i. the tip has one degree of freedom at theta = (0, 90 deg, 0): the rank of Jv",
      "ii. the singular directions are Y0 and Z0 at theta = (0, 90 deg, 0), the left null space of Jv elsewhere",
      "iii. X0 is the only direction left for the tip, which can still rotate about Y0 and Z0",
      "iv. the straight-up arm (theta = (0, 90 deg, 0), or turned about Z0) has a Type I elbow lock along Z0 and a "
      "Type II overhead lock across its plane",
      "iv. a stretched elbow is a Type I singularity and a tip above the base a Type II one"};
  std::vector<Oracle> out;
  for (const char* f : {"opspace::directions", "opspace::singularity_type", "opspace::analyse_singularities",
                        "opspace::self_motion_curvature", "opspace::directional_hessian"})
    out.push_back({f, "the singularity analysis of problem 4 (singularity.hpp)", analysis});
  return out;
}

}  // namespace opspace::grading::forbidden
