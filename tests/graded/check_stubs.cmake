cmake_minimum_required(VERSION 3.22)
# Runs the grader on exercises/ and requires a total of 0, provided exercises/ are the stubs
# as shipped (each problem's SHA-256 sum is in its folder: problems/<key>/stub.sha256). Once a
# student has edited them the check does not apply and is skipped; in CI a mismatch is an error
# (a stale manifest).
#
#   check:  cmake -DGRADER=<hw2-grade> -DEXERCISES_DIR=exercises -P tests/graded/check_stubs.cmake
#   update: cmake -DEXERCISES_DIR=exercises -DWRITE=ON -P tests/graded/check_stubs.cmake
set(repo "${CMAKE_CURRENT_LIST_DIR}/../..")
include("${repo}/grader/problems.cmake")
opspace_read_problems("${repo}/problems.txt")
set(stale "")
foreach(key IN LISTS OPSPACE_PROBLEM_KEYS)
  set(manifest "${repo}/problems/${key}/stub.sha256")
  set(hash "missing")
  if(EXISTS "${EXERCISES_DIR}/p${key}.cpp")
    file(SHA256 "${EXERCISES_DIR}/p${key}.cpp" hash)
  endif()
  if(WRITE)
    file(WRITE "${manifest}" "${hash}  p${key}.cpp\n")
    message("wrote ${manifest}")
    continue()
  endif()
  set(expected "")
  if(EXISTS "${manifest}")
    file(READ "${manifest}" expected)
  endif()
  if(NOT expected STREQUAL "${hash}  p${key}.cpp\n")
    list(APPEND stale "p${key}.cpp")
  endif()
endforeach()
if(WRITE)
  return()
endif()

if(stale)
  if("$ENV{CI}" STREQUAL "true")
    message(FATAL_ERROR "exercises/ differ from the stubs' manifests (problems/<key>/stub.sha256): ${stale}.\n"
      "If a stub was changed on purpose, update the manifests:\n"
      "  cmake -DEXERCISES_DIR=exercises -DWRITE=ON -P tests/graded/check_stubs.cmake")
  endif()
  message("SKIPPED: exercises/ have been edited, so the untouched-stub check does not apply")
  return()
endif()

# With WORK: also results.json and the report's page (issue 41): results.json valid, under 1 MB
# and escaped (check_results_page.cmake), and on both each test not written yet in one line,
# without a plot (issue 58). Seen to fail: on the page of the grader before issue 58's last item,
# which drew a figure for each failed simulated test of the stubs.
set(outputs "")
if(WORK)
  file(REMOVE_RECURSE "${WORK}")
  file(MAKE_DIRECTORY "${WORK}")
  set(outputs --gradescope "${WORK}/results.json" --html "${WORK}/report.html")
endif()
execute_process(COMMAND "${GRADER}" ${outputs} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the grader exited with ${rc}:\n${out}\n${err}")
endif()
if(NOT out MATCHES "\nTotal: 0 / [0-9.]+ points")
  message(FATAL_ERROR "the untouched stubs earned points; a test that a stub passes cannot fail:\n${out}")
endif()
# The report too: a test not written yet is its status and one line, no judged value, hint or
# replay, which would describe the stub alone (seen in the report before issue 58).
if(out MATCHES "\n +(judged|hint|replay it): ")
  message(FATAL_ERROR "the stubs' report shows judged values, hints or replays of tests not written yet:\n${out}")
endif()
# A grading that earned nothing names the first problem of problems.txt as where to start.
list(GET OPSPACE_PROBLEM_KEYS 0 first)
if(NOT out MATCHES "Where to start: open exercises/p${first}\\.cpp \\([^\n]+; guide problems/${first}/guide\\.md\\)\nand grade it alone: bash scripts/grade --problem ${first}\n")
  message(FATAL_ERROR "the stubs' report does not say to start with problem ${first}, the first of problems.txt:\n${out}")
endif()
if(WORK)
  execute_process(COMMAND ${CMAKE_COMMAND} -DJSON=${WORK}/results.json -P ${CMAKE_CURRENT_LIST_DIR}/check_results_page.cmake
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the stubs' results.json")
  endif()
  # Every test of the stubs is not written yet (docs/grader.md): on Gradescope each says so in one
  # line, without plots. Before issue 58 the stubs' 41 tests took 17 screens of the page, with 19
  # plots; 8 simulated tests, judging a run an earlier test made, did not say "not written yet".
  file(READ "${WORK}/results.json" json)
  string(JSON count LENGTH "${json}" tests)
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    string(JSON name GET "${json}" tests ${i} name)
    string(JSON output GET "${json}" tests ${i} output)
    string(JSON format GET "${json}" tests ${i} output_format)
    # One line of text (no <pre>, no <img>): the only newline is the line's own end.
    if(NOT format STREQUAL "text" OR NOT output MATCHES "^- not written yet: [^\n]*\n$")
      message(FATAL_ERROR "the stubs' '${name}' does not say 'not written yet' in one line, alone:\n${output}")
    endif()
  endforeach()
  message("ok   the stubs' results.json: each of the ${count} tests is one line, 'not written yet', without a plot")
  file(READ "${WORK}/report.html" page)
  # The page too: each failed simulated test's section, not written yet, is its status and one
  # line, without a figure (before, the stubs' page drew a plot for each of them). The page's
  # lines joined, each section then starts a line of its own (and no ; splits a match into two
  # items of a CMake list).
  string(REPLACE ";" "," page "${page}")
  string(REPLACE "\n" " " page "${page}")
  string(REPLACE "<section " "\n" page "${page}")
  string(REGEX MATCHALL "\nclass=\"test fail\"[^\n>]*data-simulated=\"1\"[^\n>]*>" failed "${page}")
  string(REGEX MATCHALL "\nclass=\"test fail\"[^\n>]*data-simulated=\"1\"[^\n>]*>[^\n]*<figure " drawn "${page}")
  string(REGEX MATCHALL "\nclass=\"test fail\"[^\n>]*data-simulated=\"1\" data-not-written=\"1\"> <h3>[^\n]*</h3> <p class=\"not-written\">not written yet: [^<]*</p> </section>"
         one_line "${page}")
  list(LENGTH failed failed_count)
  list(LENGTH drawn drawn_count)
  list(LENGTH one_line one_line_count)
  if(failed_count EQUAL 0 OR NOT drawn_count EQUAL 0 OR NOT one_line_count EQUAL failed_count)
    message(FATAL_ERROR "the stubs' page: ${failed_count} failed simulated tests, ${drawn_count} of them with a figure, "
                        "${one_line_count} saying 'not written yet' in one line alone")
  endif()
  message("ok   the stubs' page: each of the ${failed_count} failed simulated tests says 'not written yet' in one line, without a figure")
endif()
message("the untouched stubs score 0")
