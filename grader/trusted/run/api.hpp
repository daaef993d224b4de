/// @file api.hpp
/// The student-written functions of each problem, as std::function members: the graded suite
/// is written once against this struct, and the grader fills it with functions that ask a
/// problem's runner (remote_api.hpp), while the suite's own tests fill it with the reference
/// solutions and known-wrong variants linked into the test program (linked_api.hpp).
#pragma once

#include <cstdint>
#include <functional>

#include "protocol/problems.hpp"

namespace opspace::grading {

/// A function with the type of a student function, e.g. Fn<decltype(hw2::p1b::control)>.
template <class F>
using Fn = std::function<F>;

/// Each problem's slots, one per row of its table (problems/<key>/functions.hpp): P1aApi ...
/// P4Api, each member named as the contract's function, e.g. P1bApi::control.
#define OPSPACE_SLOT(problem, code, Code, name) Fn<decltype(hw2::problem::name)> name;
#define OPSPACE_PROBLEM_API(arg, problem, Problem, key, byte, FUNCTIONS) \
  struct Problem##Api {                                                  \
    FUNCTIONS(OPSPACE_SLOT)                                              \
  };
OPSPACE_PROBLEMS(OPSPACE_PROBLEM_API, ~)
#undef OPSPACE_PROBLEM_API
#undef OPSPACE_SLOT

/// Every graded function of problem set 2.
struct Hw2Api {
#define OPSPACE_PROBLEM_MEMBER(arg, problem, Problem, key, byte, FUNCTIONS) Problem##Api problem;
  OPSPACE_PROBLEMS(OPSPACE_PROBLEM_MEMBER, ~)  ///< p1a ... p4: each problem's slots
#undef OPSPACE_PROBLEM_MEMBER
  /// Tells implementations apart: the simulated runs, shared by several tests, are cached
  /// per identity. Each runner set, the reference and each known-wrong variant has its own.
  std::uint64_t identity = 0;
};

}  // namespace opspace::grading
