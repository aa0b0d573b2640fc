# Run by the test lfd-SanitizerSuite (Testing/CMakeLists.txt):
#   cmake -DSOURCE_DIR=... -DBINARY_DIR=... -DCXX_COMPILER=clang++-14
#         -DC_COMPILER=clang-14 -DPYTHON=... -DSHARED_DATA_DIR=... [-DCCACHE=...]
#         -P SanitizerSuite.cmake
# Configures and builds the sanitizer tree (ASan + UBSan + libFuzzer
# instrumentation, no Python package, no lfd tool) in BINARY_DIR, then runs its C++ tests
# (label cxx) and fuzz tests (label fuzz) in one ctest call. Fails (exit 1)
# when a step fails.

function (run what)
  message(STATUS "== ${what}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "sanitizer suite: ${what} failed (${result})")
  endif ()
endfunction ()

set(launcher "")
if (CCACHE)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CCACHE} -DCMAKE_C_COMPILER_LAUNCHER=${CCACHE})
endif ()
# -O1: the sanitizers' usual level, fast enough for the rendering tests.
# A unity build, as Utilities/setup.sh configures the main tree: half the CPU.
# NDEBUG stays: without it VTK's test driver traps floating-point exceptions,
# and Mesa's software renderer (not ours) raises one creating its context.
run("configure ${BINARY_DIR}" "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${BINARY_DIR}" -G Ninja
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG"
  "-DCMAKE_C_FLAGS_RELEASE=-O1 -DNDEBUG"
  "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_C_COMPILER=${C_COMPILER}" ${launcher}
  "-DPython3_EXECUTABLE=${PYTHON}" "-DLFD_SHARED_DATA_DIR=${SHARED_DATA_DIR}"
  -DBUILD_TESTING=ON -DLFD_WRAP_PYTHON=OFF -DLFD_BUILD_APPLICATIONS=OFF -DLFD_SANITIZE=ON -DLFD_FUZZ=ON)
cmake_host_system_information(RESULT cores QUERY NUMBER_OF_LOGICAL_CORES)
run("build" "${CMAKE_COMMAND}" --build "${BINARY_DIR}" -j ${cores})

# Leaks are not checked: Debian's VTK, Mesa and OpenImageIO keep
# process-lifetime allocations whose reports would drown real findings.
set(ENV{ASAN_OPTIONS} "detect_leaks=0:abort_on_error=0:strict_string_checks=1")
set(ENV{UBSAN_OPTIONS} "print_stacktrace=1:halt_on_error=1")
run("C++ and fuzz tests under ASan + UBSan" "${CMAKE_CTEST_COMMAND}" --test-dir "${BINARY_DIR}"
  -L "^(cxx|fuzz)$" -j ${cores} --output-on-failure)
