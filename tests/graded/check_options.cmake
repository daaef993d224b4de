cmake_minimum_required(VERSION 3.22)
# hw2-grade's --timeout: a bad value is refused before anything is graded, with exit code 2 and
# a message quoting it (an unknown problem key, a non-number, zero, no key before '='); --help
# shows the per-problem form. (That a problem's own limit applies to its tests alone, the
# regrade test proves: carol's hanging 1a stops at 1a's 5 s while bob's problem 3 has 60 s.)
#   cmake -DGRADER=<hw2-grade> -P check_options.cmake
foreach(bad "9z=5" "1a=abc" "1a=0" "=5" "abc" "1a=" "1a=-1" "4=86401")
  execute_process(COMMAND "${GRADER}" --timeout "${bad}" --problem 1a OUTPUT_VARIABLE out ERROR_VARIABLE err
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "--timeout '${bad}' exited with '${rc}', expected 2 (a bad command line):\n${out}${err}")
  endif()
  string(REPLACE "+" "\\+" quoted "${bad}")
  if(NOT err MATCHES "--timeout" OR NOT err MATCHES "${quoted}")
    message(FATAL_ERROR "--timeout '${bad}' was refused without quoting it:\n${err}")
  endif()
  if(out MATCHES "grading problem|Total:")
    message(FATAL_ERROR "--timeout '${bad}' was refused only after grading began:\n${out}")
  endif()
endforeach()
execute_process(COMMAND "${GRADER}" --help OUTPUT_VARIABLE out RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT out MATCHES "KEY=SECONDS")
  message(FATAL_ERROR "--help does not show --timeout KEY=SECONDS (exit ${rc}):\n${out}")
endif()
message("every bad --timeout refused with exit code 2 and quoted")
