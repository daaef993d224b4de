cmake_minimum_required(VERSION 3.22)
# The grader's own record in a results.json (extra_data.grader, written by hw2-grade): prints
# the run's seed when the grader lost tests or problems to its own failures (a program it could
# not start, a runner it could not build), and nothing otherwise. scripts/regrade grades those
# submissions again, alone, with that seed. It never reads the report, which quotes what the
# student's code printed.
#   cmake -DJSON=results.json -P grader_status.cmake
if(NOT EXISTS "${JSON}")
  return()
endif()
file(READ "${JSON}" json)
string(JSON faults ERROR_VARIABLE bad_faults GET "${json}" extra_data grader grader_faults)
string(JSON seed ERROR_VARIABLE bad_seed GET "${json}" extra_data grader seed)
if(bad_faults OR bad_seed OR NOT faults MATCHES "^[0-9]+$" OR NOT seed MATCHES "^[1-9][0-9]*$")
  return()
endif()
if(faults GREATER 0)
  execute_process(COMMAND ${CMAKE_COMMAND} -E echo "${seed}")
endif()
