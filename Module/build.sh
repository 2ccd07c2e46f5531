#!/usr/bin/env bash
# Configures and builds TiledRayCast in ./build (or $TRC_BUILD_DIR), Release, with Ninja.
# Extra arguments go to cmake's configure step. The optional TetGen module is on here (Debian's
# libtet1.5-dev is installed by install-deps.sh); it is AGPL-3+ and only the meshing module and
# the dataset ladder link it: pass -DTILEDRAYCAST_ENABLE_TETGEN=OFF to leave it out. OpenGL errors
# are checked in this Release build too (TILEDRAYCAST_REPORT_OPENGL_ERRORS): a test fails on any.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TRC_BUILD_DIR:-$here/build}"

"$here/Module/install-deps.sh"

if [ ! -f "$build/build.ninja" ] || [ $# -gt 0 ]; then
  cmake -S "$here" -B "$build" -G Ninja \
    -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE=/usr/bin/python3 \
    -DTILEDRAYCAST_ENABLE_TETGEN=ON \
    -DTILEDRAYCAST_REPORT_OPENGL_ERRORS=ON \
    "$@"
fi
cmake --build "$build" -j "$(nproc)"
