#!/usr/bin/env bash
# Installs what is missing, builds, then runs the main job: render a tetrahedral mesh to a PNG and
# print what was done.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TRC_BUILD_DIR:-$here/build}"

"$here/Module/build.sh"

export PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
exec /usr/bin/python3 "$here/Examples/Python/render_mesh.py" "$@"
