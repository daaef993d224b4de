# The list of problems (problems.txt, at the top of the repository) for CMake: the build
# (CMakeLists.txt) and the scripts run by cmake -P (deploy/scores.cmake,
# tests/graded/check_results.cmake) include this file and call
#   opspace_read_problems(problems.txt)
# which sets, in the caller's scope, OPSPACE_PROBLEM_KEYS (1a;1b;...: in the list's order),
# OPSPACE_PROBLEM_POINTS_<key> and OPSPACE_PROBLEM_TOTAL. A line that is not "<key> <points>",
# or a key listed twice, stops with the file and line.
function(opspace_read_problems file)
  file(STRINGS "${file}" lines)
  set(keys "")
  set(total 0)
  set(number 0)
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    if(line MATCHES "^[ \t]*(#|$)")
      continue()
    endif()
    # A key is its functions' high byte in hexadecimal (grader/protocol/problems.hpp).
    if(NOT line MATCHES "^([0-9a-f][0-9a-f]?)[ \t]+([0-9]+)[ \t]*$")
      message(FATAL_ERROR "${file}:${number}: '${line}' is not '<key> <points>', with a key of one or two of 0-9 a-f")
    endif()
    set(key ${CMAKE_MATCH_1})
    if(key IN_LIST keys)
      message(FATAL_ERROR "${file}:${number}: problem ${key} is listed twice")
    endif()
    list(APPEND keys ${key})
    set(OPSPACE_PROBLEM_POINTS_${key} ${CMAKE_MATCH_2} PARENT_SCOPE)
    math(EXPR total "${total} + ${CMAKE_MATCH_2}")
  endforeach()
  if(NOT keys)
    message(FATAL_ERROR "${file} lists no problem")
  endif()
  set(OPSPACE_PROBLEM_KEYS ${keys} PARENT_SCOPE)
  set(OPSPACE_PROBLEM_TOTAL ${total} PARENT_SCOPE)
endfunction()
