# cmake -P script run by web/explorer/CMakeLists.txt: writes the explorer page when the viewer
# bundle was built (it is optional, web/CMakeLists.txt), and says why not otherwise.
file(REMOVE ${PAGE})
if(NOT EXISTS ${VIEWER})
  message(WARNING "opspace: the explorer page was not written: the viewer bundle ${VIEWER} was not built "
                  "(node and npm, see the warning above)")
  return()
endif()
execute_process(COMMAND ${PROGRAM} page ${PAGE} ${CORE} ${VIEWER} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "opspace-explorer page failed (status ${status})")
endif()
