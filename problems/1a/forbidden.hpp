/// @file problems/1a/forbidden.hpp
/// Problem 1a's answers in the library (grader/trusted/build/library_answers.hpp): the PP robot's
/// closed forms and the generalized inverses. A runner that holds one loses the tests it
/// answers. Trusted, but no secret: docs/grader.md lists them for students, and the handout's
/// grader needs them.
#pragma once

#include <string>
#include <vector>

#include "build/library_answers.hpp"
#include <problems/1a/tests.hpp>

namespace opspace::grading::forbidden {

inline std::vector<Oracle> p1a() {
  namespace id = test_id::p1a;
  const std::string ginv = id::kPseudoInverse, split = id::kSharing;
  const std::string jbar = id::kConsistentInverse;
  return {{"opspace::pp::", "the closed forms of problem 1a (lib/include/opspace/algorithms/pp_robot.hpp)", {}},
          {"opspace::pseudo_inverse", "J+ (linalg.hpp)", {ginv, split}},
          {"opspace::weighted_inverse", "J# (linalg.hpp)", {id::kWeightedInverse, jbar, split}},
          {"opspace::dynamically_consistent_inverse", "Jbar (linalg.hpp)", {jbar, split}},
          // The operational-space quantities of problems 1b-4 hold Jbar too.
          {"opspace::operational_space", "Jbar among the operational-space quantities (opspace.hpp)", {jbar, split}},
          {"opspace::nullspace_projector", "I - J_inv J (linalg.hpp)",
           {id::kPseudoInverseProjector,
            id::kWeightedProjector, id::kConsistentProjector,
            id::kFamily}}};
}

}  // namespace opspace::grading::forbidden
