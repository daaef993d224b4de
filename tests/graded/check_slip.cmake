cmake_minimum_required(VERSION 3.22)
# A fair grade (issue 46): a slip whose run stays within every bound costs the law test alone.
# Grades FILE as problem KEY's exercise (the other problems the reference's) with the real
# grader and reads results.json: the problem earns SCORE; every test of it but LOST passed, and
# each of its simulated tests shows what it judged, met ("judged: ...: met"); LOST names MISTAKE.
# Seen to fail on the grader before issue 46 (4 / 18: every simulated test withheld for the law).
#   cmake -DGRADER=hw2-grade-sol -DREPO=. -DWORK=dir -DKEY=2 -DFILE=p2_slip.cpp -DSCORE=14
#         -DLOST="2 c. " -DMISTAKE="E^+ evaluated at lambda_d" -P check_slip.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/exercises")
file(GLOB solutions "${REPO}/solutions/*.cpp")
file(COPY ${solutions} DESTINATION "${WORK}/exercises")
configure_file("${FILE}" "${WORK}/exercises/p${KEY}.cpp" COPYONLY)
execute_process(COMMAND "${GRADER}" --unprotected --problem "${KEY}" --exercises "${WORK}/exercises"
                        --gradescope "${WORK}/results.json" --seed 41
                OUTPUT_VARIABLE report ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the grader exited with ${rc}:\n${report}\n${err}")
endif()
file(READ "${WORK}/results.json" json)
string(JSON count LENGTH "${json}" tests)
math(EXPR last "${count} - 1")
set(total 0)
foreach(i RANGE ${last})
  string(JSON name GET "${json}" tests ${i} name)
  string(JSON score GET "${json}" tests ${i} score)
  string(JSON max GET "${json}" tests ${i} max_score)
  string(JSON output GET "${json}" tests ${i} output)
  math(EXPR total "${total} + ${score}")
  string(FIND "${name}" "${LOST}" lost)
  if(lost EQUAL 0)
    if(NOT score EQUAL 0)
      message(FATAL_ERROR "'${name}' earned ${score}: the slip is in the law it tests")
    endif()
    string(FIND "${output}" "likely mistake: ${MISTAKE}" named)
    if(named LESS 0)
      message(FATAL_ERROR "'${name}' does not name the slip '${MISTAKE}':\n${output}")
    endif()
  elseif(NOT score EQUAL max)
    message(FATAL_ERROR "'${name}' earned ${score} of ${max}: a slip that moves nothing it judges must cost it nothing:\n${output}")
  elseif(name MATCHES " in simulation " AND NOT output MATCHES "judged: [^\n]*: yours [^\n]*, the reference's [^\n]*: met")
    message(FATAL_ERROR "'${name}' does not show what it judged, yours and the reference's, met:\n${output}")
  endif()
endforeach()
if(NOT total EQUAL SCORE)
  message(FATAL_ERROR "problem ${KEY} earned ${total}, expected ${SCORE}:\n${report}")
endif()
message("ok   ${FILE}: ${total} points, only '${LOST}...' lost, naming the slip; every simulated test met its bound")
