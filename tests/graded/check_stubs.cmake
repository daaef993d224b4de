cmake_minimum_required(VERSION 3.22)
# Runs the grader on exercises/ and requires a total of 0, provided exercises/ are the stubs
# as shipped (their SHA-256 sums are in stubs.sha256). Once a student has edited them the
# check does not apply and is skipped; in CI a mismatch is an error (a stale manifest).
#
#   check:  cmake -DGRADER=<hw2-grade> -DEXERCISES_DIR=exercises -DMANIFEST=tests/graded/stubs.sha256 -P check_stubs.cmake
#   update: cmake -DEXERCISES_DIR=exercises -DMANIFEST=tests/graded/stubs.sha256 -DWRITE=ON -P tests/graded/check_stubs.cmake
file(GLOB sources "${EXERCISES_DIR}/*.cpp")
set(actual "")
foreach(source IN LISTS sources)
  file(SHA256 "${source}" hash)
  get_filename_component(name "${source}" NAME)
  string(APPEND actual "${hash}  ${name}\n")
endforeach()

if(WRITE)
  file(WRITE "${MANIFEST}" "${actual}")
  message("wrote ${MANIFEST}")
  return()
endif()

file(READ "${MANIFEST}" expected)
if(NOT actual STREQUAL expected)
  if("$ENV{CI}" STREQUAL "true")
    message(FATAL_ERROR "exercises/ differ from the stub manifest ${MANIFEST}.\n"
      "If a stub was changed on purpose, update the manifest:\n"
      "  cmake -DEXERCISES_DIR=exercises -DMANIFEST=tests/graded/stubs.sha256 -DWRITE=ON -P tests/graded/check_stubs.cmake")
  endif()
  message("SKIPPED: exercises/ have been edited, so the untouched-stub check does not apply")
  return()
endif()

execute_process(COMMAND "${GRADER}" OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the grader exited with ${rc}:\n${out}\n${err}")
endif()
if(NOT out MATCHES "\nTotal: 0 / [0-9.]+ points")
  message(FATAL_ERROR "the untouched stubs earned points; a test that a stub passes cannot fail:\n${out}")
endif()
message("the untouched stubs score 0")
