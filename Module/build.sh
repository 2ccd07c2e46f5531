#!/usr/bin/env bash
# Configures and builds TiledRayCast in ./build (or $TRC_BUILD_DIR), Release, with Ninja.
# Extra arguments go to cmake's configure step.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TRC_BUILD_DIR:-$here/build}"

"$here/Module/install-deps.sh"

if [ ! -f "$build/build.ninja" ] || [ $# -gt 0 ]; then
  cmake -S "$here" -B "$build" -G Ninja \
    -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE=/usr/bin/python3 \
    "$@"
fi
cmake --build "$build" -j "$(nproc)"
