#include "judge/graded_suite.hpp"

namespace opspace::grading {

std::vector<Problem> graded_suite() {
#define OPSPACE_SUITE_PROBLEM(key) problem_##key(),
  return {OPSPACE_PROBLEM_KEYS(OPSPACE_SUITE_PROBLEM)};
#undef OPSPACE_SUITE_PROBLEM
}

}  // namespace opspace::grading
