#!/usr/bin/env bash
# The benchmark of docs/benchmarks.md, in one command: every mapper on the chosen meshes (CSV),
# then the charts. On the build machine (llvmpipe):
#   Benchmarks/run_benchmarks.sh cpu <output dir>
# On the GPU machine, through the bundle (Module/bundle-gpu.sh, then on the device):
#   TRC_SKIP_CTEST=1 TRC_THEN="Benchmarks/run_benchmarks.sh gpu \$OUT" Module/run-on-gpu.sh
# "ladder" generates the dataset ladder's rungs and times our default setting on each (scaling);
# "large" the ladder's 100M and 300M rungs made in memory (their build alone, then frames), and
# meshes split over texture buffers;
# "defaults" times our settings only, over tile size, tets per pass and query interval;
# "pipelines" our two pipelines only, each at its default; "deforming" a mesh whose every point
# moves every frame (BenchmarkDeformingMesh: rebuild, upload and render per frame); "empty"
# band and spike transfer functions with and without empty-space skipping; "overlapping" 1, 2
# and 4 overlapping copies of a mesh drawn in one traversal (BenchmarkOverlappingVolumes);
# "translucent" a mesh with translucent geometry, depth peeled (BenchmarkTranslucentGeometry).
# On the GPU, 20 views a turn (18 degrees apart): an interactive rotation. At 10 (36 degrees) every
# frame is a camera jump, which the compute pipeline verifies (waits for the frame's counts).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
kind="${1:?cpu, gpu, pipelines, defaults, ladder, large, deforming, empty, overlapping or translucent}"
out="${2:?output directory}"
mkdir -p "$out"
build="${TRC_BUNDLE_ROOT:+$TRC_BUNDLE_ROOT/build}"
build="${build:-${TRC_BUILD_DIR:-$here/build}}"
python="${TRC_PYTHON_EXE:-/usr/bin/python3}"
bench="$build/Benchmarks/BenchmarkMappers"
meshes="$here/Testing/Data/Meshes"
unset DISPLAY

# The dataset ladder's rungs named (ladder torus_1m wavelet_30m ...) into $out/ladder, its log in
# $out/ladder.log; drop_ladder removes the meshes again.
ladder() {
  "$build/Benchmarks/MakeDatasetLadder" $(printf -- '--rung %s ' "$@") \
    --inputs "$here/Testing/Data/TetGenInputs" "$out/ladder" > "$out/ladder.log" 2>&1
}
drop_ladder() {
  rm -f "$out/ladder/"*.vtu
}
# The paths of the named GPU meshes (bluntfin, post: post_tets6, torus_1m: the ladder's rung,
# made here) in the array `files`.
gpu_meshes() {
  files=()
  for m in "$@"; do
    case "$m" in
      bluntfin) files+=("$meshes/bluntfin_tets.vtu") ;;
      post) files+=("$meshes/post_tets6_conforming.vtu") ;;
      torus_1m)
        ladder torus_1m
        files+=("$out/ladder/torus_1m.vtu") ;;
    esac
  done
}
# torus_1m of the ladder at 2048², our two pipelines at their defaults and the other mappers
# named ("--pt-only": the projected tetrahedra; "--no-others": none), no reference.
torus_1m_at_2048() {
  "$bench" --sweep pipelines "$@" --no-reference --size 2048 --frames 20 \
    --csv "$out/results.csv" "$out/ladder/torus_1m.vtu"
}

case "$kind" in
  cpu)
    # llvmpipe on 2 cores, 512²: our two pipelines and the projected tetrahedra side by side on
    # the meshes of the GPU run and spx (VTK's slower CPU mappers are in the CSV of earlier runs:
    # docs/benchmarks.md).
    "$bench" --sweep pipelines --pt-only --size 512 --frames 6 --csv "$out/results.csv" \
      "$meshes/spx_vistrails.vtu" "$meshes/bluntfin_tets.vtu" "$meshes/post_tets6_conforming.vtu"
    ladder torus_1m
    "$bench" --sweep pipelines --pt-only --size 512 --frames 4 --csv "$out/results.csv" "$out/ladder/torus_1m.vtu"
    drop_ladder
    suffix="llvmpipe (CPU)"
    ;;
  gpu)
    # Every mapper at 1024² (the floor scene, three meshes); torus_1m at 2048² with our two
    # pipelines and the projected tetrahedra.
    ladder torus_1m
    "$bench" --size 1024 --frames 20 --csv "$out/results.csv" "$meshes/box5_tets.vtu" \
      "$meshes/bluntfin_tets.vtu" "$meshes/post_tets6_conforming.vtu" "$out/ladder/torus_1m.vtu"
    torus_1m_at_2048 --pt-only
    drop_ladder
    suffix="GPU"
    ;;
  pipelines)
    # Our two pipelines only, each at its default, on the GPU meshes at 1024² and torus_1m at
    # 2048²: the quick check of the compute pipeline's speed, phase by phase.
    ladder torus_1m
    "$bench" --sweep pipelines --no-others --size 1024 --frames 20 --csv "$out/results.csv" \
      "$meshes/box5_tets.vtu" "$meshes/bluntfin_tets.vtu" "$meshes/post_tets6_conforming.vtu" \
      "$meshes/comb6teeth_tetgen_270k.vtu" "$out/ladder/torus_1m.vtu"
    torus_1m_at_2048 --no-others
    drop_ladder
    suffix="GPU"
    ;;
  deforming)
    # Every point moving every frame (BenchmarkDeformingMesh): rebuild, upload and render per
    # frame, on the GPU meshes and torus_1m at 1024² (here on llvmpipe: TRC_DEFORMING_SIZE=512).
    ladder torus_1m
    "$build/Benchmarks/BenchmarkDeformingMesh" --size "${TRC_DEFORMING_SIZE:-1024}" --frames 20 \
      --csv "$out/deforming.csv" "$meshes/bluntfin_tets.vtu" \
      "$meshes/post_tets6_conforming.vtu" "$out/ladder/torus_1m.vtu"
    drop_ladder
    suffix="GPU"
    ;;
  empty)
    # Empty-space skipping: a band 2 % of the scalar range wide and a spike 0.4 % wide, ours
    # with and without skipping, on the GPU meshes and torus_1m (and wavelet_30m on the GPU,
    # without the reference: its exact image takes too long), at TRC_EMPTY_SIZE (1024; 512 here).
    size="${TRC_EMPTY_SIZE:-1024}"
    rungs="torus_1m ${TRC_EMPTY_LARGE:-wavelet_30m}"
    ladder $rungs
    for tf in band spike; do
      "$bench" --ours-only --no-others --tf $tf --size "$size" --frames "${TRC_EMPTY_FRAMES:-20}" \
        --csv "$out/empty.csv" "$meshes/bluntfin_tets.vtu" "$meshes/post_tets6_conforming.vtu" \
        "$out/ladder/torus_1m.vtu"
      for f in "$out"/ladder/*.vtu; do
        case "$(basename "$f")" in
          torus_1m.vtu) ;;
          *) "$bench" --ours-only --no-others --no-reference --tf $tf --size "$size" --frames \
               "${TRC_EMPTY_FRAMES:-20}" --csv "$out/empty.csv" "$f" ;;
        esac
      done
    done
    drop_ladder
    suffix="GPU"
    ;;
  overlapping)
    # Overlapping volumes (BenchmarkOverlappingVolumes): 1, 2 and 4 copies of bluntfin, post_tets6
    # and torus_1m, integrated in one traversal, at
    # TRC_OVERLAPPING_SIZE (1024; here on llvmpipe 256 and TRC_OVERLAPPING_MESHES=bluntfin).
    gpu_meshes ${TRC_OVERLAPPING_MESHES:-bluntfin post torus_1m}
    # Shifted by 3 % of the diagonal per copy (nearly every ray through a mixture), then by 30 %
    # (the copies overlap in part: most rays cross one copy at a time).
    for shift in ${TRC_OVERLAPPING_SHIFTS:-0.03 0.3}; do
      "$build/Benchmarks/BenchmarkOverlappingVolumes" --size "${TRC_OVERLAPPING_SIZE:-1024}" \
        --frames "${TRC_OVERLAPPING_FRAMES:-20}" --counts 1,2,4 --shift "$shift" \
        --csv "$out/overlapping-$shift.csv" "${files[@]}"
    done
    drop_ladder
    suffix="GPU"
    ;;
  translucent)
    # Translucent geometry in depth order (BenchmarkTranslucentGeometry): the volume alone, the
    # translucent geometry alone, both without and with depth peeling for volumes, on bluntfin,
    # post_tets6 and torus_1m at TRC_TRANSLUCENT_SIZE (1024; TRC_TRANSLUCENT_MESHES to choose).
    gpu_meshes ${TRC_TRANSLUCENT_MESHES:-bluntfin post torus_1m}
    "$build/Benchmarks/BenchmarkTranslucentGeometry" --size "${TRC_TRANSLUCENT_SIZE:-1024}" \
      --frames "${TRC_TRANSLUCENT_FRAMES:-20}" --csv "$out/translucent.csv" "${files[@]}"
    drop_ladder
    suffix="GPU"
    ;;
  defaults)
    # The study behind the mapper's defaults: tile size, tets per pass, occlusion-query interval
    # (ours only), on the GPU meshes and the comb, whose rays re-enter up to six times.
    ladder torus_1m
    "$bench" --sweep defaults --size "${TRC_DEFAULTS_SIZE:-1024}" --frames 20 --csv "$out/defaults.csv" \
      "$meshes/bluntfin_tets.vtu" "$meshes/post_tets6_conforming.vtu" \
      "$meshes/comb6teeth_tetgen_270k.vtu" "$out/ladder/torus_1m.vtu"
    drop_ladder
    suffix="GPU"
    ;;
  large)
    # The ladder's largest rungs, made in memory (GeneratedMeshes.h: 100M and 300M tetrahedra,
    # convex and non-convex), our default at 1024², one process each (its host memory peak is
    # its own); first, what reading a mesh split over several texture buffers costs (as meshes
    # above 134M tetrahedra are on NVIDIA's GPUs), on the GPU meshes.
    gpu_meshes bluntfin post torus_1m
    "$bench" --sweep buffers --size 1024 --frames 20 --csv "$out/buffers.csv" "${files[@]}"
    drop_ladder
    rungs="${TRC_LARGE_RUNGS:-wavelet6_100m gym6_100m wavelet6_300m gym6_300m}"
    # The mapper's mesh build alone, its phases and host peak (one process a rung, as above).
    for rung in $rungs; do
      "$build/Benchmarks/BenchmarkTetMeshBuild" --generated "$rung" > "$out/build-$rung.csv" ||
        echo "$rung: build failed (status $?)"
    done
    cat "$out"/build-*.csv | awk 'NR == 1 || !/^rung,/' > "$out/large-build.csv"
    rm -f "$out"/build-*.csv
    for rung in $rungs; do
      "$bench" --sweep default --no-reference --size 1024 --frames 20 --csv "$out/large.csv" \
        "generated:$rung" || echo "$rung: failed (status $?)"
    done
    suffix="GPU"
    ;;
  ladder)
    # torus_10m and torus_30m take minutes to mesh (docs/datasets.md): not in this run.
    rungs="${TRC_LADDER_RUNGS:-wavelet_300k wavelet_1m wavelet_3m wavelet_10m wavelet_30m torus_300k torus_1m torus_3m}"
    ladder $rungs
    # Our two pipelines on every rung; the projected tetrahedra up to 3M tets (its CPU sort
    # takes seconds a frame beyond).
    for f in "$out"/ladder/*.vtu; do
      case "$(basename "$f")" in
        *_10m.vtu|*_30m.vtu) others=--no-others ;;
        *) others=--pt-only ;;
      esac
      "$bench" --sweep pipelines $others --no-reference --size 1024 --frames 20 \
        --csv "$out/ladder.csv" "$f"
      rm -f "$f"
    done
    suffix="GPU"
    ;;
esac
for csv in "$out"/results.csv "$out"/ladder.csv; do
  [ -f "$csv" ] || continue
  PYTHONPATH="$build/lib/python3/dist-packages" "$python" "$here/Benchmarks/plot_benchmarks.py" \
    "$csv" --output-dir "$out/charts" --title-suffix "$suffix" || echo "charts failed for $csv"
done
