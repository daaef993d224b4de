/// @file problems/1a/forbidden.hpp
/// Problem 1a's answers in the library (grader/trusted/library_answers.hpp): the PP robot's
/// closed forms and the generalized inverses. A runner that holds one loses the tests it
/// answers. Trusted, but no secret: docs/grader.md lists them for students, and the handout's
/// grader needs them.
#pragma once

#include <string>
#include <vector>

#include "library_answers.hpp"

namespace opspace::grading::forbidden {

inline std::vector<Oracle> p1a() {
  const std::string ginv = "iv. the pseudo-inverse is J^T (J J^T)^-1", split = "vi. J+ shares dx equally between the joints, Jbar moves only joint 2";
  const std::string jbar = "vi. the inertia-weighted inverse moves only the light link";
  return {{"opspace::pp::", "the closed forms of problem 1a (lib/include/opspace/algorithms/pp_robot.hpp)", {}},
          {"opspace::pseudo_inverse", "J+ (linalg.hpp)", {ginv, split}},
          {"opspace::weighted_inverse", "J# (linalg.hpp)", {"v. the weighted inverse is W^-1 J^T (J W^-1 J^T)^-1", jbar, split}},
          {"opspace::dynamically_consistent_inverse", "Jbar (linalg.hpp)", {jbar, split}},
          // The operational-space quantities of problems 1b-4 hold Jbar too.
          {"opspace::operational_space", "Jbar among the operational-space quantities (opspace.hpp)", {jbar, split}},
          {"opspace::nullspace_projector", "I - J_inv J (linalg.hpp)",
           {"iv. I - J+ J keeps only the self-motions that leave the end-effector still",
            "v. I - J# J is the weighted null-space projector", "vi. I - Jbar J is the dynamically consistent projector",
            "iv-vi. every inverse gives the family dq = J_inv dx + (I - J_inv J) dq0"}}};
}

}  // namespace opspace::grading::forbidden
