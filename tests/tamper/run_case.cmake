cmake_minimum_required(VERSION 3.22)
# One case of the tamper suite: a submission made of the reference solutions with one file
# replaced (CASE.cpp, configured with @RESULTS_JSON@, @WORK@, @REPO@, @GRADER@, @FAULT@,
# @TOTAL@: the points of the whole list, problems.txt) or
# patched (CASE.cmake sets TARGET, FROM, TO, PREPEND), graded by the real grader. Then, after a
# pause that lets anything the submission left behind act, the case checks that
#   - the grader exited 0 and results.json is valid and unchanged since the grader exited;
#   - nothing wrote @WORK@/pwned or @WORK@/flood.bin (outside the sandbox);
#   - results.json records no fault of the grader's own (extra_data.grader.grader_faults): every
#     failure a case causes is the submission's, and none buys it a second grading;
#   - each problem in SCORES ("1b=0;1a=23") earned exactly that;
#   - the report matches EXPECT; neither it nor results.json's texts match FORBID (regular
#     expressions) or hold a byte sequence of FORBID_BYTES (hexadecimal, ","-separated).
# Cases with ISOLATED=ON need the sandbox's private file view: skipped (SKIPPED:) without it.
#   cmake -DGRADER=hw2-grade-sol -DSOLUTIONS=solutions -DCASE=cases/<case>.cpp [-DTARGET=p1b.cpp]
#         -DWORK=dir -DREPO=root [-DTIMEOUT=seconds per test, 5] [-DPROBLEM=1b] [-DSCORES=...] [-DEXPECT=...] [-DFORBID=...] [-DFORBID_BYTES=e280a8,ff]
#         [-DFAULT=...] [-DISOLATED=ON] [-DGRADER_ARGS=--no-isolation] -P run_case.cmake
# (GRADER_ARGS=--no-isolation turns the sandbox off: then the attacks succeed, which shows
# that the cases can fail.)
if(NOT TIMEOUT)
  set(TIMEOUT 5)
endif()
# The full marks a forged score line claims (problems.txt).
include("${REPO}/grader/problems.cmake")
opspace_read_problems("${REPO}/problems.txt")
set(TOTAL ${OPSPACE_PROBLEM_TOTAL})
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/exercises")
file(GLOB solutions "${SOLUTIONS}/*.cpp")
file(COPY ${solutions} DESTINATION "${WORK}/exercises")
set(RESULTS_JSON "${WORK}/results.json")
if(CASE MATCHES "\\.cmake$")
  include("${CASE}")
  file(READ "${WORK}/exercises/${TARGET}" text)
  string(FIND "${text}" "${FROM}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${CASE}: '${FROM}' is not in solutions/${TARGET}")
  endif()
  string(REPLACE "${FROM}" "${TO}" text "${text}")
  file(WRITE "${WORK}/exercises/${TARGET}" "${PREPEND}${text}")
else()
  configure_file("${CASE}" "${WORK}/exercises/${TARGET}" @ONLY)
endif()

set(args --exercises "${WORK}/exercises" --gradescope "${RESULTS_JSON}" --timeout ${TIMEOUT} ${GRADER_ARGS})
if(PROBLEM)
  list(APPEND args --problem ${PROBLEM})
endif()
execute_process(COMMAND "${GRADER}" ${args} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc
                TIMEOUT 900)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the grader exited with '${rc}' (expected 0: grading ran):\n${out}\n${err}")
endif()
if(ISOLATED AND out MATCHES "Sandbox: [^\n]*(private view|separate user)")
  message("SKIPPED: this case needs the sandbox's private file view and separate user, not available here:\n${out}")
  return()
endif()
file(SHA256 "${RESULTS_JSON}" written)
execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 4)
file(SHA256 "${RESULTS_JSON}" later)
if(NOT written STREQUAL later)
  file(READ "${RESULTS_JSON}" forged)
  message(FATAL_ERROR "results.json changed after the grader exited:\n${forged}")
endif()
foreach(marker pwned flood.bin)
  if(EXISTS "${WORK}/${marker}")
    message(FATAL_ERROR "the submission wrote ${WORK}/${marker}, outside its sandbox")
  endif()
endforeach()
if(DEFINED EXPECT AND NOT out MATCHES "${EXPECT}")
  message(FATAL_ERROR "the report does not say '${EXPECT}':\n${out}")
endif()
if(DEFINED FORBID AND out MATCHES "${FORBID}")
  message(FATAL_ERROR "the report says '${FORBID}', which it must not:\n${out}")
endif()
# results.json's texts, decoded, must not say it either: Gradescope shows them to the student.
file(READ "${RESULTS_JSON}" json)
string(JSON shown GET "${json}" output)
string(JSON count LENGTH "${json}" tests)
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
  string(JSON text GET "${json}" tests ${i} output)
  string(APPEND shown "\n${text}")
endforeach()
if(DEFINED FORBID AND shown MATCHES "${FORBID}")
  message(FATAL_ERROR "results.json says '${FORBID}', which it must not:\n${shown}")
endif()
# FORBID_BYTES: hexadecimal byte sequences (a bidi override, U+2028, a C1 control, an invalid
# UTF-8 byte) that must appear neither in the report nor in results.json, at any byte offset.
if(DEFINED FORBID_BYTES)
  string(REPLACE "," ";" FORBID_BYTES "${FORBID_BYTES}")
  file(WRITE "${WORK}/report.txt" "${out}")
  foreach(where "${WORK}/report.txt" "${RESULTS_JSON}")
    file(READ "${where}" bytes HEX)
    foreach(sequence IN LISTS FORBID_BYTES)
      # Each place the hex digits occur, kept only at a byte boundary (an even offset). A regular
      # expression "^(..)*seq" recursed once per byte and overflowed CMake's stack (a segfault)
      # on a results.json of 43 KB.
      set(rest "${bytes}")
      set(offset 0)
      string(FIND "${rest}" "${sequence}" at)
      while(NOT at EQUAL -1)
        math(EXPR offset "${offset} + ${at}")
        math(EXPR odd "${offset} % 2")
        if(odd EQUAL 0)
          message(FATAL_ERROR "${where} holds the bytes ${sequence} raw, which the grader must show escaped:\n${out}")
        endif()
        math(EXPR next "${at} + 1")
        string(SUBSTRING "${rest}" ${next} -1 rest)
        math(EXPR offset "${offset} + 1")
        string(FIND "${rest}" "${sequence}" at)
      endwhile()
    endforeach()
  endforeach()
endif()

string(JSON faults GET "${json}" extra_data grader grader_faults)
if(NOT faults EQUAL 0)
  message(FATAL_ERROR "results.json records ${faults} fault(s) of the grader's own, where the submission caused every failure:\n${out}")
endif()

# Scores per problem, from results.json (tests are named "<key> ...").
string(REPLACE "," ";" SCORES "${SCORES}")
foreach(expectation IN LISTS SCORES)
  string(REGEX MATCH "^([^=]+)=(.+)$" _ "${expectation}")
  set(key "${CMAKE_MATCH_1}")
  set(expected "${CMAKE_MATCH_2}")
  set(total 0)
  foreach(i RANGE ${last})
    string(JSON name GET "${json}" tests ${i} name)
    string(JSON score GET "${json}" tests ${i} score)
    if(name MATCHES "^${key} ")
      math(EXPR total "${total} + ${score}")
    endif()
  endforeach()
  if(NOT total EQUAL expected)
    message(FATAL_ERROR "problem ${key} earned ${total}, expected ${expected}:\n${out}")
  endif()
endforeach()
message("as expected: ${SCORES}")
