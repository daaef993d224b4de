cmake_minimum_required(VERSION 3.22)
# A built runner is reused only by the grader that built it. Its cached report holds what that
# grader found (calls to the library's oracles, the include check): a grader with other oracles
# or rules must compile the file anew, or a student's cached runner would escape the new rules.
# Two copies of the grader that differ by bytes appended to the executable (ignored when it
# runs) stand for an old and a new grader:
#   the first copy compiles p1a.cpp, and reuses that runner when run again (the cache works);
#   the second copy compiles it anew (the cache does not cross graders).
#   cmake -DGRADER=<hw2-grade-sol> -DEXERCISES=<solutions> -DWORK=<dir> -P check_cache.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
# A suffix of this run's own: a copy from an earlier run of this test must not match.
string(RANDOM LENGTH 24 run)
foreach(copy old new)
  file(COPY_FILE "${GRADER}" "${WORK}/grader-${copy}")
  file(APPEND "${WORK}/grader-${copy}" "opspace cache check: ${copy} grader of run ${run}\n")
  file(CHMOD "${WORK}/grader-${copy}" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE
       WORLD_READ WORLD_EXECUTE)
endforeach()
function(grade copy expected)
  execute_process(COMMAND "${WORK}/grader-${copy}" --exercises "${EXERCISES}" --problem 1a
                  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the ${copy} grader exited with ${rc}:\n${err}\n${out}")
  endif()
  string(REGEX MATCH "exercises/p1a.cpp: [^\n]*" said "${err}")
  if(NOT said MATCHES "${expected}")
    message(FATAL_ERROR "the ${copy} grader should have said '${expected}' of p1a.cpp; it said '${said}':\n${err}")
  endif()
  if(NOT out MATCHES "Total: 23 / 23 points")
    message(FATAL_ERROR "the ${copy} grader did not give the reference 1a full marks:\n${out}")
  endif()
  message("${copy} grader: ${said}")
endfunction()
grade(old "compiled$")
grade(old "its runner is reused$")
grade(new "compiled$")
message("a runner is reused by the grader that built it, and by no other")
