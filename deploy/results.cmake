cmake_minimum_required(VERSION 3.22)
# Completes Gradescope's results.json after the grader: puts the submission's notes
# (collect_submission.sh) at the top of its "output". When the grader wrote no valid
# results.json (it could not run), writes one that says so, with a score of 0, so that
# Gradescope always has a results file. CMake is used because it is already there (the
# build needs it) and parses JSON.
#
#   cmake -DJSON=results.json [-DNOTES=notes.txt] [-DREASON=text] -P results.cmake

# The notes name the submission's files as the student named them: "<h2>...</h2>.cpp" is a file
# name. results.json's texts are "text" (output_format), and their & < > are written as HTML
# entities besides (as the grader writes its own, grader/trusted/student_text.hpp), so that no
# page renders a tag of the student's.
function(html_escape text out)
  string(REPLACE "&" "&amp;" text "${text}")
  string(REPLACE "<" "&lt;" text "${text}")
  string(REPLACE ">" "&gt;" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# A JSON string literal of `text`: the notes and the reason are printable ASCII and newlines
# (collect_submission.sh cleans file names), so escaping \ " and the line ends is enough.
function(json_string text out)
  string(REPLACE "\\" "\\\\" text "${text}")
  string(REPLACE "\"" "\\\"" text "${text}")
  string(REPLACE "\r" "" text "${text}")
  string(REPLACE "\t" " " text "${text}")
  string(REPLACE "\n" "\\n" text "${text}")
  set(${out} "\"${text}\"" PARENT_SCOPE)
endfunction()

set(notes "")
if(DEFINED NOTES AND EXISTS "${NOTES}")
  file(READ "${NOTES}" notes)
  html_escape("${notes}" notes)
endif()
html_escape("${REASON}" REASON)

set(valid OFF)
if(EXISTS "${JSON}")
  file(READ "${JSON}" json)
  string(JSON score ERROR_VARIABLE bad GET "${json}" score)
  string(JSON type ERROR_VARIABLE bad_tests TYPE "${json}" tests)
  if(NOT bad AND NOT bad_tests AND type STREQUAL "ARRAY")
    set(valid ON)
  endif()
endif()

if(valid)
  if(notes STREQUAL "")
    return()
  endif()
  string(JSON output ERROR_VARIABLE bad GET "${json}" output)
  if(bad)
    set(output "")
  endif()
  json_string("About your submission:\n${notes}\n${output}" value)
  string(JSON json SET "${json}" output "${value}")
  string(JSON json SET "${json}" output_format "\"text\"")
else()
  if(NOT DEFINED REASON OR REASON STREQUAL "")
    set(REASON "the grader wrote no results")
  endif()
  json_string("${notes}\nThe autograder could not grade this submission: ${REASON}.\nThis is not your fault if your files are named as asked: tell your instructor." value)
  # extra_data.not_graded: why, for the class page (grader/trusted/class_results.hpp).
  json_string("${REASON}" reason)
  set(json "{\"score\": 0, \"output\": ${value}, \"output_format\": \"text\", \"visibility\": \"visible\", \"extra_data\": {\"not_graded\": ${reason}}, \"tests\": []}")
endif()
file(WRITE "${JSON}.tmp" "${json}\n")
file(RENAME "${JSON}.tmp" "${JSON}")
