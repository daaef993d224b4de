cmake_minimum_required(VERSION 3.22)
# Completes Gradescope's results.json after the grader: puts the submission's notes
# (collect_submission.sh) at the top of its "output", and the files they say are missing or
# misnamed in extra_data.submission (for the class page). When the grader wrote no valid
# results.json (it could not run), writes one that says so, with a score of 0, so that
# Gradescope always has a results file. CMake is used because it is already there (the
# build needs it) and parses JSON.
#
#   cmake -DJSON=results.json [-DNOTES=notes.txt] [-DREASON=text] -P results.cmake

# The notes name the submission's files as the student named them: "<h2>...</h2>.cpp" is a file
# name. results.json's texts are "text" (output_format), and their & < > are written as HTML
# entities besides (as the grader writes its own, grader/trusted/common/student_text.hpp), so that no
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
endif()
# extra_data.submission: the exercise files missing (or symbolic links), the files named
# otherwise and the zips refused, from the notes' own sentences (collect_submission.sh), for the class page's "Look
# at these first" (grader/trusted/class/class_results.hpp). Names as the notes show them, HTML-escaped.
set(missing "")
string(REGEX MATCHALL "\np[0-9a-z]+\\.cpp( is missing from your submission|: '[^\n]*' is a symbolic link)" found "\n${notes}")
foreach(line IN LISTS found)
  string(REGEX MATCH "p[0-9a-z]+\\.cpp" file "${line}")
  string(APPEND missing ", \"${file}\"")
endforeach()
set(misnamed "")
if(notes MATCHES "(^|\n)Not graded, the name is not one the grader reads: ([^\n]*) \\(the grader reads only")
  html_escape("${CMAKE_MATCH_2}" names)
  json_string("${names}" names)
  set(misnamed "${names}")
endif()
string(REGEX REPLACE "^, " "" missing "${missing}")
# A zip refused (collect_submission.sh, hw2-unzip, apps/unzip.cpp): its whole note, HTML-escaped.
set(refused "")
string(REGEX MATCHALL "\nYour zip '[^\n]*' was refused, not unzipped: [^\n]*" found "\n${notes}")
foreach(line IN LISTS found)
  string(STRIP "${line}" line)
  html_escape("${line}" line)
  json_string("${line}" line)
  string(APPEND refused ", ${line}")
endforeach()
string(REGEX REPLACE "^, " "" refused "${refused}")
set(submission "{\"missing\": [${missing}], \"misnamed\": [${misnamed}], \"refused\": [${refused}]}")
html_escape("${notes}" notes)
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
  string(JSON extra ERROR_VARIABLE no_extra TYPE "${json}" extra_data)
  if(no_extra OR NOT extra STREQUAL "OBJECT")
    string(JSON json SET "${json}" extra_data "{}")
  endif()
  string(JSON json SET "${json}" extra_data submission "${submission}")
  string(JSON json SET "${json}" output_format "\"text\"")
else()
  if(NOT DEFINED REASON OR REASON STREQUAL "")
    set(REASON "the grader wrote no results")
  endif()
  json_string("${notes}\nThe autograder could not grade this submission: ${REASON}.\nThis is not your fault if your files are named as asked: tell your instructor." value)
  # extra_data.not_graded: why, for the class page (grader/trusted/class/class_results.hpp).
  json_string("${REASON}" reason)
  set(json "{\"score\": 0, \"output\": ${value}, \"output_format\": \"text\", \"visibility\": \"visible\", \"extra_data\": {\"not_graded\": ${reason}, \"submission\": ${submission}}, \"tests\": []}")
endif()
file(WRITE "${JSON}.tmp" "${json}\n")
file(RENAME "${JSON}.tmp" "${JSON}")
