#include "suite.hpp"

namespace opspace::grading {

std::vector<Problem> graded_suite() { return {problem_1a()}; }

}  // namespace opspace::grading
