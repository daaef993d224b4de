cmake_minimum_required(VERSION 3.22)
# Fresh random inputs, replayable: the report of a 1a that answers I or zero everywhere (whose
# findings print the random inputs, e.g. "A(m1 = 8.385455, m2 = ...)"; not all zero, which the
# report would show as "not written yet", without its inputs) is identical for one
# --seed twice and differs for another seed, so that answers recorded in one run do not fit
# the next.
#   cmake -DGRADER=<hw2-grade> -DWORK=<dir> -P check_seed.cmake
file(MAKE_DIRECTORY "${WORK}")
file(WRITE "${WORK}/p1a.cpp" "#include <problems/1a/contract.hpp>
namespace opspace::hw2::p1a {
DegreesOfFreedom degrees_of_freedom() { return {}; }
Eigen::Matrix2d mass_matrix(double, double) { return Eigen::Matrix2d::Identity(); }
Eigen::RowVector2d task_jacobian() { return Eigen::RowVector2d::Zero(); }
Eigen::Vector2d pseudo_inverse(const Eigen::RowVector2d&) { return Eigen::Vector2d::Zero(); }
Eigen::Vector2d weighted_inverse(const Eigen::RowVector2d&, const Eigen::Matrix2d&) { return Eigen::Vector2d::Zero(); }
Eigen::Vector2d inertia_weighted_inverse(const Eigen::RowVector2d&, const Eigen::Matrix2d&) { return Eigen::Vector2d::Zero(); }
Eigen::Matrix2d nullspace_projector(const Eigen::RowVector2d&, const Eigen::Vector2d&) { return Eigen::Matrix2d::Zero(); }
Eigen::Vector2d inverse_kinematics_step(const Eigen::RowVector2d&, const Eigen::Vector2d&, double, const Eigen::Vector2d&) { return Eigen::Vector2d::Zero(); }
DisplacementSplit split_displacement(double, double, double) { return {}; }
}
")
function(report seed out)
  execute_process(COMMAND "${GRADER}" --exercises "${WORK}" --problem 1a --seed ${seed} OUTPUT_VARIABLE text
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the grader exited with ${rc}:\n${text}")
  endif()
  string(REGEX REPLACE "Built in [^\n]*" "" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()
report(5 first)
report(5 again)
report(6 other)
if(NOT first STREQUAL again)
  message(FATAL_ERROR "--seed 5 twice gave two reports:\n${first}\n---\n${again}")
endif()
if(first STREQUAL other)
  message(FATAL_ERROR "--seed 5 and --seed 6 drew the same inputs:\n${first}")
endif()
if(NOT first MATCHES "A\\(m1 = ")
  message(FATAL_ERROR "the report shows no random input to compare:\n${first}")
endif()
message("one seed replays its inputs; another draws new ones")
