#include "suite.hpp"

namespace opspace::grading {

std::vector<Problem> graded_suite() { return {problem_1a(), problem_1b(), problem_2(), problem_3(), problem_4()}; }

}  // namespace opspace::grading
