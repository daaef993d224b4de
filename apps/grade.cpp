// hw2-grade: grades the exercise files of OPSPACE_DEFAULT_EXERCISES (exercises/ in hw2-grade,
// solutions/ in hw2-grade-sol), or of --exercises DIR. The grader itself lives in
// grader/ (trusted/ and suite/): it builds each problem's runner from its file and never runs the
// student's code in this process.
#include "grader.hpp"

int main(int argc, char** argv) {
  return opspace::grading::grader_main(argc, argv, OPSPACE_DEFAULT_EXERCISES);
}
