#!/usr/bin/env bash
# Installs the Debian 12 packages that building, testing and running TiledRayCast need, if any
# is missing. Needs root (or sudo) only when something must be installed.
set -euo pipefail

packages=(
  cmake ninja-build g++ make           # build tools
  libvtk9-dev vtk9 python3-vtk9        # VTK 9.1: headers, wrapping tools, Python modules
  libglew-dev libegl-dev libgl-dev     # headers of the GL libraries VTK links (EGL for headless)
  libegl-mesa0 libgl1-mesa-dri         # Mesa's llvmpipe for machines without a GPU
  libosmesa6-dev                       # OSMesa: only docs/headless-osmesa (why it is not used)
  xvfb xauth                           # X server for the tests that use VTK's X window
  tetgen libtet1.5-dev                 # TetGen for the optional meshing module and the ladder
  xz-utils                             # Module/bundle-gpu.sh compresses the GPU bundle
  openmpi-bin                          # mpirun: ParaView's ranks in the MPI tests (ParaView/Testing)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "TiledRayCast: installing missing Debian packages: ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo="sudo"
  else
    echo "error: these packages are missing and this is not root: ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
