#!/usr/bin/env bash
# The ParaView figures of docs/parallel.md on the GPU machine, in one device call, after
# ParaView/run-on-gpu.sh unpack has unpacked every part (docs/parallel.md, "On a GPU server"):
#   ParaView/gpu-figures.sh OUT [--ranks "1 2"] [--frames 20] [--size 1024] [--redistribution
#                           "2 4 8"] [--mappers "Tiled ray cast|Projected tetra|Empty view"]
#                           mesh.vtu ...
# 1. What the machine is: its GPUs, ParaView's version, Open MPI relocated (mpirun -np 2 true).
# 2. ParaView/benchmark.sh --egl on every mesh, "Tiled ray cast" and "Projected tetra" side by
#    side and the empty view (ParaView's own cost a frame), at each rank count of --ranks:
#    OUT/paraview-gpu.csv. 20 frames a turn (18 degrees apart), as Benchmarks/ on the GPU.
# 3. With --redistribution, the first mesh again, ours only, at those rank counts: ParaView's
#    redistribution time against the frame (OUT/paraview-gpu.csv, same columns).
# Every log, JSON and our mapper's images (the projected tetrahedra's are left out: 16 MiB a file
# come back) go into OUT/paraview-gpu-logs.tar.xz, for the image checks made back on the build
# machine (docs/parallel.md).
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:?output directory}"
shift
ranks="1 2"
frames=20
size=1024
redistribution=""
mappers="Tiled ray cast|Projected tetra|Empty view"
meshes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --ranks) ranks="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    --size) size="$2"; shift 2 ;;
    --redistribution) redistribution="$2"; shift 2 ;;
    --mappers) mappers="$2"; shift 2 ;;
    *) meshes+=("$1"); shift ;;
  esac
done
[ ${#meshes[@]} -gt 0 ] || { echo "gpu-figures: no mesh named" >&2; exit 1; }
run="$here/ParaView/run-on-gpu.sh"
export TRC_PV_TIMEOUT="${TRC_PV_TIMEOUT:-240}"  # one pvbatch run hung must not take the call
# GPU ranks bound to one core stall (docs/parallel.md): unbound unless told otherwise.
export TRC_MPIRUN_ARGS="${TRC_MPIRUN_ARGS---bind-to none}"
work="$(mktemp -d)"
mkdir -p "$out"
{
  date -u
  nvidia-smi -L 2>&1 || true
  "$run" run pvbatch --version 2>&1
  "$run" run timeout 60 mpirun --allow-run-as-root -np 2 true && echo "mpirun -np 2: ok"
} > "$out/paraview-gpu-machine.log" 2>&1
cat "$out/paraview-gpu-machine.log"

# What came so far goes to OUT after each mesh: a call cut short still brings it back.
collect() {
  cp "$work/paraview-gpu.csv" "$out/" 2> /dev/null
  (cd "$work" && tar -cf - --exclude='*Projected_tetra*.png' --exclude='*.csv' . | xz -T0 -6) \
    > "$out/paraview-gpu-logs.tar.xz"
}
for mesh in "${meshes[@]}"; do
  "$run" run "$here/ParaView/benchmark.sh" --egl --ranks "$ranks" --frames "$frames" \
    --size "$size" --mappers "$mappers" --csv "$work/paraview-gpu.csv" "$mesh"
  collect
done
if [ -n "$redistribution" ]; then
  "$run" run "$here/ParaView/benchmark.sh" --egl --ranks "$redistribution" --frames 5 \
    --size "$size" --mappers "Tiled ray cast" --csv "$work/paraview-gpu.csv" "${meshes[0]}"
  collect
fi
rm -rf "$work"
cat "$out/paraview-gpu.csv" 2> /dev/null
