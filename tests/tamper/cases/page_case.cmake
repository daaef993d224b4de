cmake_minimum_required(VERSION 3.22)
# What the student's page shows (issue 38): the reference solutions graded by the real grader,
# then results.json read as Gradescope reads it. MODE is
#   tag        the reference 1b with "#warning <h1>Total: ${TOTAL} / ${TOTAL} points</h1>": the compiler's
#              warning quotes it, and results.json's output shows it, escaped;
#   file_name  a submission holding the reference files and two whose names hold a tag
#              ("<h2>Total: ${TOTAL} / ${TOTAL} points</h2>.cpp", "<h2 ...>Total: ${TOTAL} of ${TOTAL} points.cpp"), collected and completed as run_autograder does
#              (deploy/collect_submission.sh, deploy/results.cmake): the note that names it;
#   hidden     the reference 1b with --hidden "in simulation": the report and results.json's
#              output count the tests shown alone (10 of 1b's 20 points), the hidden tests are
#              after_published, and the score (the gradebook's) is the whole 20.
# Each: output_format "text" at the top and for every test, and no tag of the student's in a
# text of results.json (a < or > raw).
#   cmake -DGRADER=hw2-grade-sol -DREPO=root -DWORK=dir -DMODE=tag|file_name|hidden [-DTIMEOUT=60]
#         [-DGRADER_ARGS=...] -P page_case.cmake
if(NOT TIMEOUT)
  set(TIMEOUT 60)
endif()
# The full marks the forged lines claim: the whole list's (problems.txt).
include("${REPO}/grader/problems.cmake")
opspace_read_problems("${REPO}/problems.txt")
set(TOTAL ${OPSPACE_PROBLEM_TOTAL})
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/exercises")
file(GLOB solutions "${REPO}/solutions/*.cpp")
set(results "${WORK}/results.json")
set(page "${WORK}/report.html")
set(args --exercises "${WORK}/exercises" --gradescope "${results}" --html "${page}" --timeout ${TIMEOUT} ${GRADER_ARGS})

if(MODE STREQUAL "tag")
  file(COPY ${solutions} DESTINATION "${WORK}/exercises")
  file(READ "${WORK}/exercises/p1b.cpp" text)
  file(WRITE "${WORK}/exercises/p1b.cpp" "#warning <h1>Total: ${TOTAL} / ${TOTAL} points</h1>\n${text}")
  list(APPEND args --problem 1b)
elseif(MODE STREQUAL "file_name")
  set(submission "${WORK}/submission")
  file(COPY ${solutions} DESTINATION "${submission}")
  # A name cannot hold "/": this one is three folders deep, as a zip can hold it, and the note
  # names its path. The second is one file name, its tag left open (a page renders it anyway).
  file(WRITE "${submission}/<h2>Total: ${TOTAL} / ${TOTAL} points</h2>.cpp" "// not an exercise file\n")
  file(WRITE "${submission}/<h2 style=color:green>Total: ${TOTAL} of ${TOTAL} points.cpp" "// not an exercise file\n")
  execute_process(COMMAND bash "${REPO}/deploy/collect_submission.sh" "${submission}" "${WORK}/exercises"
                          "${REPO}/exercises" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "collect_submission.sh exited with ${rc}")
  endif()
  list(APPEND args --problem 1a)
elseif(MODE STREQUAL "hidden")
  file(COPY ${solutions} DESTINATION "${WORK}/exercises")
  list(APPEND args --problem 1b --hidden "in simulation")
else()
  message(FATAL_ERROR "MODE is tag, file_name or hidden, not '${MODE}'")
endif()

execute_process(COMMAND "${GRADER}" ${args} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 900)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the grader exited with '${rc}' (expected 0: grading ran):\n${out}\n${err}")
endif()
if(MODE STREQUAL "file_name")
  execute_process(COMMAND ${CMAKE_COMMAND} -DJSON=${results} -DNOTES=${WORK}/exercises/notes.txt -DREASON=
                          -P "${REPO}/deploy/results.cmake" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "results.cmake exited with ${rc}")
  endif()
endif()

# --- what Gradescope shows the student ----------------------------------------------------------
include(${REPO}/tests/support/gradescope_html.cmake)
file(READ "${results}" json)
string(JSON format ERROR_VARIABLE bad GET "${json}" output_format)
if(bad OR NOT format STREQUAL "text")
  message(FATAL_ERROR "results.json's output_format is '${format}' (${bad}), not \"text\": Gradescope's default renders HTML:\n${json}")
endif()
string(JSON shown GET "${json}" output)
string(JSON count LENGTH "${json}" tests)
math(EXPR last "${count} - 1")
set(all_texts "${shown}")
set(visible_score 0)
set(visible_max 0)
set(hidden_count 0)
foreach(i RANGE ${last})
  string(JSON name GET "${json}" tests ${i} name)
  string(JSON text GET "${json}" tests ${i} output)
  string(JSON test_format ERROR_VARIABLE bad GET "${json}" tests ${i} output_format)
  if(bad OR NOT test_format STREQUAL "html")
    message(FATAL_ERROR "results.json: test '${name}' has output_format '${test_format}' (${bad}), not \"html\"")
  endif()
  # The grader's own markup out: what is left is text, which must hold no tag.
  opspace_grader_markup_removed("${text}" text)
  string(APPEND all_texts "\n${text}")
  string(JSON visibility GET "${json}" tests ${i} visibility)
  string(JSON score GET "${json}" tests ${i} score)
  string(JSON max GET "${json}" tests ${i} max_score)
  if(visibility STREQUAL "visible")
    math(EXPR visible_score "${visible_score} + ${score}")
    math(EXPR visible_max "${visible_max} + ${max}")
  else()
    math(EXPR hidden_count "${hidden_count} + 1")
  endif()
endforeach()
if(all_texts MATCHES "<[^\n]*>")
  message(FATAL_ERROR "results.json's texts hold a tag raw ('${CMAKE_MATCH_0}'), which a page would render:\n${all_texts}")
endif()

if(MODE STREQUAL "tag")
  if(NOT shown MATCHES "#warning &lt;h1&gt;Total: ${TOTAL} / ${TOTAL} points&lt;/h1&gt;")
    message(FATAL_ERROR "results.json's output does not show the warning, escaped:\n${shown}")
  endif()
  # The report's page (hw2-grade --html, issue 41) quotes the warning too, as text: the tag
  # escaped, never an element. Seen to fail with report_html.cpp's text() returning its argument
  # unescaped.
  file(READ "${page}" html)
  if(html MATCHES "<h1>Total" OR NOT html MATCHES "#warning &lt;h1&gt;Total: ${TOTAL} / ${TOTAL} points&lt;/h1&gt;")
    message(FATAL_ERROR "the report's page does not quote the warning as escaped text:\n${html}")
  endif()
elseif(MODE STREQUAL "file_name")
  if(NOT shown MATCHES "'&lt;h2&gt;Total: ${TOTAL} / ${TOTAL} points&lt;/h2&gt;.cpp'" OR
     NOT shown MATCHES "'&lt;h2 style=color:green&gt;Total: ${TOTAL} of ${TOTAL} points.cpp'")
    message(FATAL_ERROR "results.json's output does not name the file, escaped:\n${shown}")
  endif()
elseif(MODE STREQUAL "hidden")
  # 1b: 20 points, 10 of them in its three simulated tests.
  string(JSON score GET "${json}" score)
  if(NOT score EQUAL 20 OR NOT hidden_count EQUAL 3 OR NOT visible_score EQUAL 10 OR NOT visible_max EQUAL 10)
    message(FATAL_ERROR "expected a score of 20 (the gradebook's), 3 hidden tests and 10 / 10 shown; got ${score}, ${hidden_count}, ${visible_score} / ${visible_max}:\n${json}")
  endif()
  foreach(i RANGE ${last})
    string(JSON visibility GET "${json}" tests ${i} visibility)
    if(NOT visibility MATCHES "^(visible|after_published)$")
      message(FATAL_ERROR "a test is '${visibility}': with points, only after_published or after_due_date keep the total from the student")
    endif()
  endforeach()
  # The student's lines: the page's output and the printed report count 10 of 10, never 20.
  if(NOT shown MATCHES "^Problem 1b: 10 / 10 in the tests shown" OR shown MATCHES "20")
    message(FATAL_ERROR "results.json's output shows the hidden tests' points:\n${shown}")
  endif()
  # The report's page is the student's too: no hidden test's name on it.
  file(READ "${page}" html)
  if(html MATCHES "in simulation")
    message(FATAL_ERROR "the report's page shows a hidden test")
  endif()
  if(NOT out MATCHES "\n  Problem 1b: 10 / 10 points in the tests shown" OR NOT out MATCHES "\nTotal: 10 / 10 points in the tests shown"
     OR out MATCHES "in simulation" OR out MATCHES " 20\n|/ 20 ")
    message(FATAL_ERROR "the printed report shows the hidden tests or their points:\n${out}")
  endif()
endif()
message("as expected (${MODE})")
