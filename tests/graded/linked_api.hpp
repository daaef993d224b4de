/// @file linked_api.hpp
/// The functions linked into a test program of our own (the reference solutions, to which the
/// mutants swap in known-wrong variants): the suite's own tests grade them in-process. The
/// grader never includes this header: it does not link a student's code.
#pragma once

#include "run/api.hpp"

namespace opspace::grading {

/// The hw2 functions this program links: every slot, from the problems' tables.
inline Hw2Api linked_api() {
  Hw2Api api{};
#define OPSPACE_LINK_SLOT(problem, code, Code, name) api.problem.name = &hw2::problem::name;
  OPSPACE_FUNCTIONS(OPSPACE_LINK_SLOT)
#undef OPSPACE_LINK_SLOT
  api.identity = 1;
  return api;
}

}  // namespace opspace::grading
