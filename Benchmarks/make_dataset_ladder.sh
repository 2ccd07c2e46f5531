#!/usr/bin/env bash
# Writes the dataset ladder (docs/datasets.md) into OUTDIR, one rung per process, each under
# /usr/bin/time so that its peak resident memory is its own; checks every file (--verify) and
# prints the Markdown table of docs/datasets.md.
#
#   Benchmarks/make_dataset_ladder.sh OUTDIR [MakeDatasetLadder selection options]
#   e.g. Benchmarks/make_dataset_ladder.sh /tmp/ladder --max-tets 1000000
#        Benchmarks/make_dataset_ladder.sh /tmp/ladder --family torus
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TRC_BUILD_DIR:-$here/build}"
exe="$build/Benchmarks/MakeDatasetLadder"
if [ $# -lt 1 ] || [ ! -x "$exe" ]; then
  echo "usage: $0 OUTDIR [--family F] [--rung R] [--max-tets N] [--compressor C]" >&2
  echo "(needs $exe: run Module/build.sh first)" >&2
  exit 2
fi
out="$1"
shift
mkdir -p "$out"

rungs=$("$exe" --list "$@" | awk -F'|' 'NR > 2 { gsub(/ /, "", $2); print $2 }')
# Columns: the program's own (wall-clock seconds to generate and to write, file size), then from
# /usr/bin/time: CPU seconds (user + system) of the whole process, its peak RSS (with --verify,
# which reads the file back, included).
echo "| rung | convex | points | tetrahedra | generate (s) | write (s) | file (MiB) | CPU (s) | peak RSS (MiB) |"
echo "|---|---|---|---|---|---|---|---|---|"
status=0
for rung in $rungs; do
  log="$out/$rung.log"
  if /usr/bin/time -v -o "$out/$rung.time" "$exe" --rung "$rung" --verify "$@" "$out" >"$log" 2>&1; then
    rss_kb=$(awk -F': ' '/Maximum resident set size/ { print $2 }' "$out/$rung.time")
    cpu=$(awk -F': ' '/User time|System time/ { s += $2 } END { printf "%.1f", s }' "$out/$rung.time")
    # The program's row, with /usr/bin/time's CPU time and peak RSS in place of its own last column.
    grep "^| $rung " "$log" | awk -F'|' -v rss="$rss_kb" -v cpu="$cpu" \
      'BEGIN { OFS = "|" } { $9 = sprintf(" %s | %.0f ", cpu, rss / 1024); print }'
  else
    echo "| $rung | FAILED, see $log | | | | | | | |"
    status=1
  fi
done
exit $status
