# lfd-InstalledConsumer: as a user of the installed library would (the
# lfd-Install fixture installed the build into PREFIX): configures, builds
# and runs Consumer/ (find_package(LightFieldDeform), link, render), then
# runs the installed lfd --version.
# Arguments: -DPREFIX= -DSOURCE_DIR= -DWORK_DIR= -DVERSION=
file(REMOVE_RECURSE "${WORK_DIR}")

function (run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status
    OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}\n${err}")
  endif ()
  set(output "${out}" PARENT_SCOPE)
endfunction ()

run("configuring the consumer" "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/Consumer"
  -B "${WORK_DIR}" -G Ninja -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${PREFIX}")
run("building the consumer" "${CMAKE_COMMAND}" --build "${WORK_DIR}")
# The consumer finds the libraries through the prefix only (no build tree
# on any path).
run("running the consumer" "${CMAKE_COMMAND}" -E env "LD_LIBRARY_PATH=${PREFIX}/lib"
  "${WORK_DIR}/lfdConsumer")
message(STATUS "${output}")

run("lfd --version" "${PREFIX}/bin/lfd" --version)
if (NOT output STREQUAL "lfd ${VERSION}\n")
  message(FATAL_ERROR "lfd --version printed '${output}', expected 'lfd ${VERSION}'")
endif ()
