/// @file problems/4/forbidden.hpp
/// Problem 4's answers in the library (grader/trusted/build/library_answers.hpp): the singularity
/// analysis. A runner that holds one loses the tests it answers. Trusted, but no secret:
/// docs/grader.md lists them for students, and the handout's grader needs them.
#pragma once

#include <string>
#include <vector>

#include "build/library_answers.hpp"
#include <problems/4/tests.hpp>

namespace opspace::grading::forbidden {

inline std::vector<Oracle> p4() {
  namespace id = test_id::p4;
  const std::vector<std::string> analysis = {
      id::kRank,
      id::kDirections,
      id::kDirectionLeft,
      id::kStraightUpTypes,
      id::kTypesElsewhere};
  std::vector<Oracle> out;
  for (const char* f : {"opspace::directions", "opspace::singularity_type", "opspace::analyse_singularities",
                        "opspace::self_motion_curvature", "opspace::directional_hessian"})
    out.push_back({f, "the singularity analysis of problem 4 (singularity.hpp)", analysis});
  return out;
}

}  // namespace opspace::grading::forbidden
