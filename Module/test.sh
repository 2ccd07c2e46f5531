#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite under ctest.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TRC_BUILD_DIR:-$here/build}"

"$here/Module/build.sh"

cd "$build"
# Rendering tests that use VTK's X window run under a virtual X server; the rest need no X.
xvfb-run -a -s "-screen 0 1280x1024x24" \
  ctest --output-on-failure -j "$(nproc)" "$@"
