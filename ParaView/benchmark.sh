#!/usr/bin/env bash
# Frame times of "Tiled ray cast" and "Projected tetra" in pvbatch (the figures of
# docs/paraview.md): each mesh at --size pixels, a first frame, then --frames frames with the
# camera turning. Needs `make paraview` first (the Release plugin in build/paraview/plugin).
#   ParaView/benchmark.sh [--size 1024] [--frames 10] [mesh.vtu ...]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TRC_BUILD_DIR:-$here/build}"
root="${TRC_PARAVIEW_ROOT:-$build/paraview/root}"
plugin="$build/paraview/plugin/lib/paraview-5.11/plugins/TiledRayCast/TiledRayCast.so"
size=1024
frames=10
meshes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --size) size="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    *) meshes+=("$1"); shift ;;
  esac
done
if [ ${#meshes[@]} -eq 0 ]; then
  meshes=("$here/Testing/Data/Meshes/bluntfin_tets.vtu" "$here/Testing/Data/Meshes/post_tets6_conforming.vtu")
fi
[ -f "$plugin" ] || { echo "no plugin at $plugin: run make paraview first" >&2; exit 1; }
out="$build/paraview/benchmark"
mkdir -p "$out"
export LD_LIBRARY_PATH="$root/usr/lib/x86_64-linux-gnu"
export PYTHONPATH="$root/usr/lib/python3/dist-packages"
for mesh in "${meshes[@]}"; do
  for mapper in "Tiled ray cast" "Projected tetra"; do
    name="$(basename "$mesh" .vtu)_${mapper// /_}_$size"
    # Retried: two xvfb-run -a started at once (another suite's) may pick the same display.
    for attempt in 1 2 3; do
      if xvfb-run -a -s "-screen 0 $((size + 256))x$((size + 256))x24" "$root/usr/bin/pvbatch" \
        "$here/ParaView/Testing/pvbatch_render.py" --plugin "$plugin" --mesh "$mesh" \
        --mapper "$mapper" --size "$size" --frames "$frames" --output "$out/$name" \
        >"$out/$name.log" 2>&1; then
        grep -E "^rendered|^statistics" "$out/$name.log"
        break
      fi
      echo "($name: pvbatch failed, attempt $attempt: $out/$name.log)"
    done
  done
done
