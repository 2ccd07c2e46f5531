#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite under ctest.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TRC_BUILD_DIR:-$here/build}"

"$here/Module/build.sh"

cd "$build"
# No X server: without DISPLAY, vtkRenderWindow::New() is the EGL window of
# TiledRayCast::RenderingHeadless (Mesa's llvmpipe through EGL's surfaceless platform here, a GPU
# where there is one). The tests of VTK's X window (label X) start their own xvfb-run.
env -u DISPLAY ctest --output-on-failure -j "$(nproc)" "$@"
