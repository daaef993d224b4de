/// @file functions.hpp
/// The student's functions as the grader walks them: each Hw2Api slot with its protocol code,
/// derived from the problems' tables (protocol/problems.hpp). The remote api, the answers'
/// sizes and decoding, the recording of a test's calls, the replay of known mistakes and the
/// handout's record and replay all walk it.
#pragma once

#include <string>

#include "run/api.hpp"
#include "protocol/protocol.hpp"

namespace opspace::grading {

/// Calls visit(code, member) for every function of `api`, in the tables' order.
template <class Api, class Visit>
void for_each_function(Api& api, Visit&& visit) {
#define OPSPACE_VISIT_SLOT(problem, code, Code, name) visit(protocol::Function::Code, api.problem.name);
  OPSPACE_FUNCTIONS(OPSPACE_VISIT_SLOT)
#undef OPSPACE_VISIT_SLOT
}

/// The problem a function belongs to, its key in problems.txt ("1a": the code's high byte); ""
/// for a code of no problem.
inline std::string problem_of(protocol::Function function) {
  switch (static_cast<std::uint32_t>(function) >> 8) {
#define OPSPACE_PROBLEM_CASE(arg, problem, Problem, key, byte, FUNCTIONS) \
  case byte: return key;
    OPSPACE_PROBLEMS(OPSPACE_PROBLEM_CASE, ~)
#undef OPSPACE_PROBLEM_CASE
    default: return "";
  }
}

/// A function's name in its problem's contract, e.g. "mass_matrix" ("" for an unknown code).
inline const char* function_name(protocol::Function function) {
  switch (function) {
#define OPSPACE_FUNCTION_CASE(problem, code, Code, name) \
  case protocol::Function::Code: return #name;
    OPSPACE_FUNCTIONS(OPSPACE_FUNCTION_CASE)
#undef OPSPACE_FUNCTION_CASE
  }
  return "";
}

}  // namespace opspace::grading
