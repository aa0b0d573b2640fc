#!/usr/bin/env bash
# The two commands of the README:
#   Utilities/run.sh demo [lfd demo options]   set up, build, run the demo
#   Utilities/run.sh test [ctest options]      set up, build, run every test
# Both run under xvfb-run: VTK's OpenGL needs an X server (Mesa llvmpipe).
# -noreset: by default Xvfb resets when its last client disconnects, and a
# test that connects during that reset aborts ("bad X server connection").
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${LFD_BUILD_DIR:-$here/build}
what=${1:-}
shift || true

case "$what" in
  demo)
    "$here/Utilities/setup.sh"
    exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$build/bin/lfd" demo "$@"
    ;;
  test)
    "$here/Utilities/setup.sh"
    # Tests in parallel, one per core: tests sharing a port hold a CTest
    # resource lock, the sanitizer suite runs alone (RUN_SERIAL).
    exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
      ctest --test-dir "$build" -j "$(nproc)" --output-on-failure "$@"
    ;;
  *)
    echo "usage: Utilities/run.sh demo|test [options]" >&2
    exit 2
    ;;
esac
