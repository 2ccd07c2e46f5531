#!/usr/bin/env bash
# The one place that knows which Debian releases are supported and what differs between them:
# sourced by install-deps.sh, fetch-paraview.sh, build-plugin.sh, test-debian13.sh and
# bundle-gpu.sh (and run by ParaView/Testing/CMakeLists.txt: `debian-release.sh paraview`
# prints the ParaView series). It reads /etc/os-release (or $TRC_OS_RELEASE) and sets:
#   trc_debian            12 or 13
#   trc_codename          bookworm or trixie
#   trc_vtk               VTK's series in libvtk9-dev (9.1, 9.3)
#   trc_python            Debian's python3 series (3.11, 3.13)
#   trc_paraview          ParaView's series (5.11, 5.13) and trc_paraview_deb the version tested
#   trc_packages          the Debian packages that building, testing and running the module need
# Any other system gets a clear message and exit status 1 (trc_release_or_die).
trc_release_read() {
  local file="${TRC_OS_RELEASE:-/etc/os-release}" id="" version_id="" codename=""
  if [ -r "$file" ]; then
    id="$(. "$file" && echo "${ID:-}")"
    version_id="$(. "$file" && echo "${VERSION_ID:-}")"
    codename="$(. "$file" && echo "${VERSION_CODENAME:-}")"
  fi
  trc_release_name="${id:-unknown} ${version_id:-?} (${codename:-?})"
  trc_debian=""
  [ "$id" = debian ] || return 1
  case "$version_id:$codename" in
    12:* | :bookworm) trc_release_for 12 ;;
    13:* | :trixie) trc_release_for 13 ;;
    *) return 1 ;;
  esac
}

# The settings of release $1 (12 or 13), whatever this system is (test-debian13.sh).
trc_release_for() {
  trc_debian="$1"
  trc_packages=(
    cmake ninja-build g++ make           # build tools
    libvtk9-dev vtk9 python3-vtk9        # VTK: headers, wrapping tools, Python modules
    libglew-dev libegl-dev libgl-dev     # headers of the GL libraries VTK links (EGL for headless)
    libegl-mesa0 libgl1-mesa-dri         # Mesa's llvmpipe for machines without a GPU
    libosmesa6-dev                       # OSMesa: only docs/headless-osmesa (why it is not used)
    xvfb xauth                           # X server for the tests that use VTK's X window
    tetgen libtet1.5-dev                 # TetGen for the optional meshing module and the ladder
    xz-utils                             # Module/bundle-gpu.sh compresses the GPU bundle
    openmpi-bin                          # mpirun: ParaView's ranks in the MPI tests (ParaView/Testing)
  )
  case "$trc_debian" in
    12)
      trc_codename=bookworm trc_vtk=9.1 trc_python=3.11
      trc_paraview=5.11 trc_paraview_deb="5.11.0+dfsg-1+b1"
      ;;
    13)
      trc_codename=trixie trc_vtk=9.3 trc_python=3.13
      trc_paraview=5.13 trc_paraview_deb="5.13.2+dfsg-3"
      ;;
    *) echo "trc_release_for: no Debian $1 here" >&2; return 1 ;;
  esac
}

trc_release_or_die() {
  if ! trc_release_read; then
    echo "TiledRayCast: this system is $trc_release_name; supported are Debian 12 (bookworm:" \
      "VTK 9.1, ParaView 5.11) and Debian 13 (trixie: VTK 9.3, ParaView 5.13)." \
      "Elsewhere, build with CMake against VTK 9.1 to 9.3 yourself (README)." >&2
    exit 1
  fi
}

if [ "${BASH_SOURCE[0]}" = "$0" ]; then
  set -euo pipefail
  trc_release_or_die
  case "${1:-}" in
    paraview) echo "$trc_paraview" ;;
    python) echo "$trc_python" ;;
    vtk) echo "$trc_vtk" ;;
    debian | "") echo "$trc_debian" ;;
    *) echo "usage: $0 [debian|vtk|python|paraview]" >&2; exit 2 ;;
  esac
fi
