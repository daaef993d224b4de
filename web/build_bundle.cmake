# cmake -P script run by web/CMakeLists.txt: copies the web sources into the build tree, runs
# `npm ci` there (pinned by package-lock.json) and bundles with esbuild. A failure is a
# warning, not a build error: the stamp records it so that it is not retried on every build
# (delete the stamp, or the build's web/ folder, to retry).
file(REMOVE ${BUNDLE} ${EXPLORER_VIEWER} ${LIVE_VIEWER})
file(COPY ${SOURCE_DIR}/package.json ${SOURCE_DIR}/package-lock.json ${SOURCE_DIR}/build.mjs
     ${SOURCE_DIR}/src ${SOURCE_DIR}/test DESTINATION ${BINARY_DIR})

function(give_up why)
  message(WARNING "opspace: the 3D replay viewer was not bundled: ${why}\n"
                  "The programs still run and plot; they will say that no replay page was written. "
                  "To retry: rm ${STAMP} and build again.")
  file(WRITE ${STAMP} "failed: ${why}\n")
  return()
endfunction()

# --engine-strict: a package that needs a newer node than this machine's fails here, at build
# time, with npm's EBADENGINE error, not later when the replay test runs.
execute_process(COMMAND ${NPM} ci --engine-strict --no-audit --no-fund --loglevel=error
                WORKING_DIRECTORY ${BINARY_DIR} RESULT_VARIABLE npm_status)
if(NOT npm_status EQUAL 0)
  give_up("`npm ci` failed (status ${npm_status}): is the npm registry reachable? "
          "Does a package need a newer node (EBADENGINE above)?")
  return()
endif()
execute_process(COMMAND ${NODE} build.mjs ${BUNDLE} ${EXPLORER_VIEWER} ${LIVE_VIEWER} WORKING_DIRECTORY ${BINARY_DIR} RESULT_VARIABLE esbuild_status)
if(NOT esbuild_status EQUAL 0 OR NOT EXISTS ${BUNDLE})
  give_up("esbuild failed (status ${esbuild_status})")
  return()
endif()
file(WRITE ${STAMP} "ok: ${BUNDLE}\n")
