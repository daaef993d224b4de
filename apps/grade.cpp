// hw2-grade: grades the functions linked into this program (exercises/ in hw2-grade,
// solutions/ in hw2-grade-sol). The command itself lives in tests/graded/grader.cpp.
#include "api.hpp"
#include "grader.hpp"

int main(int argc, char** argv) {
  return opspace::grading::grader_main(argc, argv, opspace::grading::linked_api(), OPSPACE_GRADED_LIBRARY);
}
