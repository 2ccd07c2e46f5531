#!/usr/bin/env bash
# Builds the ParaView plugin against the private ParaView root (5.11 on Debian 12, 5.13 on Debian
# 13: Module/debian-release.sh; fetched and unpacked first by fetch-paraview.sh when missing) and
# prints how to load it.
#   ParaView/build-plugin.sh [--build-type Release|Debug] [--build-dir DIR] [--quiet]
# Defaults: Release in build/paraview/plugin (what `make paraview` builds). The test suite builds
# a Debug plugin in build/paraview/plugin-debug: the one Debug build of the module's sources
# that CI compiles (vtkOpenGLCheckErrorMacro and the asserts are compiled only without NDEBUG).
# Exit status 125 when ParaView cannot be fetched here (see fetch-paraview.sh).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TRC_BUILD_DIR:-$here/build}"
root="${TRC_PARAVIEW_ROOT:-$build/paraview/root}"
type=Release
dir=""
quiet=0
while [ $# -gt 0 ]; do
  case "$1" in
    --build-type) type="$2"; shift 2 ;;
    --build-dir) dir="$2"; shift 2 ;;
    --quiet) quiet=1; shift ;;
    *) echo "usage: $0 [--build-type Release|Debug] [--build-dir DIR] [--quiet]" >&2; exit 2 ;;
  esac
done
if [ -z "$dir" ]; then
  if [ "$type" = Release ]; then dir="$build/paraview/plugin"; else dir="$build/paraview/plugin-${type,,}"; fi
fi

. "$here/Module/debian-release.sh"
trc_release_or_die
pv="$trc_paraview"

"$here/Module/install-deps.sh" # compilers, CMake, Ninja, xvfb-run
"$here/ParaView/fetch-paraview.sh"

# ParaView's wrapping tools (vtkWrapClientServer-pv5.11 or -pv5.13 and others) run during the build and
# link ParaView's libraries, which are not on the system's library path.
export LD_LIBRARY_PATH="$root/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
start=$(date +%s.%N)
if [ ! -f "$dir/build.ninja" ]; then
  # Debug keeps NDEBUG undefined (the checks) but optimises: at -O0 the mesh build and the CPU
  # side made the ParaView tests 3-5 times slower (9 min instead of 2-3 on two cores).
  cmake -S "$here/ParaView" -B "$dir" -G Ninja \
    -DCMAKE_BUILD_TYPE="$type" -DCMAKE_CXX_FLAGS_DEBUG="-O2" -DCMAKE_C_FLAGS_DEBUG="-O2" \
    -DParaView_DIR="$root/usr/lib/x86_64-linux-gnu/cmake/paraview-$pv" \
    -DPython3_EXECUTABLE=/usr/bin/python3 >"$dir.configure.log" 2>&1 ||
    { cat "$dir.configure.log" >&2; exit 1; }
fi
cmake --build "$dir" -j "$(nproc)"
end=$(date +%s.%N)
plugin="$dir/lib/paraview-$pv/plugins/TiledRayCast/TiledRayCast.so"
echo "TiledRayCast: ParaView plugin ($type) built in $(awk "BEGIN { printf \"%.0f\", $end - $start }") s: $plugin"
if [ "$quiet" -eq 0 ]; then
  cat <<EOT

Run ParaView $pv from the private root (Debian's pvpython and pvbatch need an X server):
  export LD_LIBRARY_PATH=$root/usr/lib/x86_64-linux-gnu
  export PYTHONPATH=$root/usr/lib/python3/dist-packages
  xvfb-run -a $root/usr/bin/pvbatch your_script.py
and load the plugin, either in the script:
  LoadPlugin('$plugin', remote=False, ns=globals())
or for every session:
  export PV_PLUGIN_PATH=$(dirname "$plugin")
Then pick it: display.SetRepresentationType('Volume'); display.SelectMapper = 'Tiled ray cast'
(docs/paraview.md has a whole script).
EOT
fi
