#!/usr/bin/env bash
# Frame times of "Tiled ray cast" and "Projected tetra" in pvbatch (the figures of
# docs/paraview.md and docs/parallel.md): each mesh at --size pixels, a first frame, then --frames
# frames with the camera turning, on each number of ranks of --ranks (mpirun; several ranks share
# the machine's GPUs, rank modulo GPUs), into a CSV.
#   ParaView/benchmark.sh [--size 1024] [--frames 10] [--ranks "1 2"] [--egl] [--csv FILE]
#                         [--mappers "Tiled ray cast|Projected tetra|Empty view"] [mesh.vtu ...]
# "Empty view": the same view and frames with the volume hidden, what ParaView itself costs a
# frame. ParaView's rendering log is on (PARAVIEW_LOG_RENDERING_VERBOSITY=INFO): the CSV takes
# IceT's render and composite times from it. TRC_PV_TIMEOUT: seconds for one pvbatch run (900).
# --egl: no X server, every rank on the plugin's EGL window (a GPU, or llvmpipe); without it one
# rank runs under xvfb-run, as before. Needs `make paraview` (the Release plugin) here, or, on the
# GPU machine, ParaView/run-on-gpu.sh run ParaView/benchmark.sh --egl ... (pvbatch and mpirun on
# PATH, the plugin in TRC_PV_PLUGIN).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TRC_BUILD_DIR:-$here/build}"
root="${TRC_PARAVIEW_ROOT:-$build/paraview/root}"
if [ -z "${TRC_PV_PLUGIN:-}" ]; then
  # shellcheck source=../Module/debian-release.sh
  . "$here/Module/debian-release.sh"
  trc_release_or_die
fi
plugin="${TRC_PV_PLUGIN:-$build/paraview/plugin/lib/paraview-${trc_paraview:-}/plugins/TiledRayCast/TiledRayCast.so}"
size=1024
frames=10
ranks_list="1"
egl=0
csv=""
mappers="Tiled ray cast|Projected tetra"
meshes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --size) size="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    --ranks) ranks_list="$2"; shift 2 ;;
    --egl) egl=1; shift ;;
    --csv) csv="$2"; shift 2 ;;
    --mappers) mappers="$2"; shift 2 ;;
    *) meshes+=("$1"); shift ;;
  esac
done
if [ ${#meshes[@]} -eq 0 ]; then
  meshes=("$here/Testing/Data/Meshes/bluntfin_tets.vtu" "$here/Testing/Data/Meshes/post_tets6_conforming.vtu")
fi
[ -f "$plugin" ] || { echo "no plugin at $plugin: run make paraview first" >&2; exit 1; }
pvbatch="$(command -v pvbatch || echo "$root/usr/bin/pvbatch")"
if [ "$pvbatch" = "$root/usr/bin/pvbatch" ]; then
  export LD_LIBRARY_PATH="$root/usr/lib/x86_64-linux-gnu"
  export PYTHONPATH="$root/usr/lib/python3/dist-packages"
fi
out="${csv:+$(dirname "$csv")}"
out="${out:-$build/paraview/benchmark}"
mkdir -p "$out"
csv="${csv:-$out/paraview.csv}"
[ -f "$csv" ] || echo "mesh,cells,mapper,ranks,size,first_frame_s,frame_median_s,frame_min_s,redistribution_s,gpu_total_ms,gpu_raycast_ms,icet_render_ms,icet_composite_ms,renderer" > "$csv"
# TRC_MPIRUN_ARGS: more options for mpirun (e.g. "--bind-to none").
mpirun=(mpirun --oversubscribe ${TRC_MPIRUN_ARGS:-})
[ "$(id -u)" -eq 0 ] && mpirun+=(--allow-run-as-root)

IFS='|' read -r -a mapper_names <<< "$mappers"
for mesh in "${meshes[@]}"; do
  for mapper in "${mapper_names[@]}"; do
    for ranks in $ranks_list; do
      name="$(basename "$mesh" .vtu)_${mapper// /_}_${size}_${ranks}"
      args=("$here/ParaView/Testing/pvbatch_render.py" --plugin "$plugin" --mesh "$mesh"
        --size "$size" --frames "$frames" --output "$out/$name")
      # TRC_PV_RENDER_ARGS: more options for pvbatch_render.py (e.g. --synchronous-statistics).
      args+=(${TRC_PV_RENDER_ARGS:-})
      if [ "$mapper" = "Empty view" ]; then
        args+=(--mapper "Tiled ray cast" --empty-view)
      else
        args+=(--mapper "$mapper")
      fi
      [ "$ranks" -gt 1 ] && args+=(--time-redistribution)
      ok=0
      # ParaView's rendering log (its scopes' times, IceT's own timers) goes into the log.
      if [ "$egl" = 1 ] || [ "$ranks" -gt 1 ]; then
        env -u DISPLAY PARAVIEW_LOG_RENDERING_VERBOSITY=INFO timeout "${TRC_PV_TIMEOUT:-900}" "${mpirun[@]}" -np "$ranks" "$pvbatch" "${args[@]}" \
          > "$out/$name.log" 2>&1 && ok=1
      else
        # Retried: two xvfb-run -a started at once (another suite's) may pick the same display.
        for attempt in 1 2 3; do
          if PARAVIEW_LOG_RENDERING_VERBOSITY=INFO xvfb-run -a -s "-screen 0 $((size + 256))x$((size + 256))x24" "$pvbatch" "${args[@]}" \
            > "$out/$name.log" 2>&1; then
            ok=1
            break
          fi
        done
      fi
      if [ "$ok" != 1 ]; then
        echo "($name: pvbatch failed: $out/$name.log)"
        tail -n 5 "$out/$name.log"
        continue
      fi
      grep -E "^rendered|^statistics|INFO\| .*rank 0 renders" "$out/$name.log" | cut -c1-300 || true
      # The machine's own Python (the environment may point PYTHONHOME at pvbatch's 3.11).
      env -u PYTHONHOME -u PYTHONPATH python3 - "$out/$name.json" "$mesh" "$mapper" "$ranks" "$size" "$out/$name.log" >> "$csv" << 'EOF'
import json, re, statistics, sys
result = json.load(open(sys.argv[1]))
frames = result["frame_s"] or [result["first_frame_s"]]
stats = result.get("statistics") or ""
def number(pattern):
    m = re.search(pattern, stats)
    return m.group(1) if m else ""
renderer = ""
# IceT's timers per rank, each frame (ParaView's rendering log): the rank's own render (the
# slowest rank's median) and the compositing on rank 0 (median), over the timed frames.
icet = {}
for line in open(sys.argv[6], errors="replace"):
    m = re.search(r"rank 0 renders with EGL on \S+ -?\d+ \([^)]*\): (.*?), OpenGL", line)
    if m:
        renderer = m.group(1)
    m = re.search(r"\[pvbatch\.?(\d*) *\].*ICET_(RENDER|COMPOSITE)_TIME: ([0-9.]+)", line)
    if m:
        icet.setdefault((m.group(2), int(m.group(1) or 0)), []).append(float(m.group(3)) * 1000)
def icet_median(kind, ranks):
    values = [statistics.median(v[-len(frames):]) for (k, r), v in icet.items()
              if k == kind and r in ranks]
    return "%.3f" % max(values) if values else ""
print(",".join(str(v) for v in (
    sys.argv[2].split("/")[-1], result["cells"], sys.argv[3], sys.argv[4], sys.argv[5],
    "%.4f" % result["first_frame_s"], "%.5f" % statistics.median(frames), "%.5f" % min(frames),
    "%.3f" % result["redistribution_s"] if result["redistribution_s"] is not None else "",
    number(r"total ([0-9.]+)"), number(r"ray casting ([0-9.]+)"),
    icet_median("RENDER", range(1024)), icet_median("COMPOSITE", [0]), '"%s"' % renderer)))
EOF
    done
  done
done
echo "benchmark: $csv"
