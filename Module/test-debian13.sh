#!/usr/bin/env bash
# make test-debian13: the same sources built and tested against Debian 13's VTK 9.3 and ParaView
# 5.13 (issue 27), on this Debian 12 machine. A Debian 13 root made from Debian's packages with
# mmdebstrap (a Debian package, installed here if missing) is cached in build/debian13/root and
# reused; it is made again when its package list (Debian 13's set of Module/install-deps.sh)
# changes, or when an earlier run was interrupted before it was complete (the stamp is written
# last). Inside it the module is configured and built in /build (build/debian13/root/build here)
# from the source tree, bind-mounted read-only at /src, and the whole suite runs, the ParaView
# tests included: their setup test fetches ParaView 5.13 into the root's /build/paraview/root (as
# `make test` does on a Debian 13 machine; apt-get inside the root, with this machine's
# resolv.conf) and builds the plugin. Extra arguments go to ctest.
#   Module/test-debian13.sh --shell     a shell in the root, with the same mounts
#   Module/test-debian13.sh --bundle    the GPU bundle of the root's build (Module/bundle-gpu.sh
#                                       run inside the root), into .bundle/debian13/; without
#                                       Python unless TRC_BUNDLE_PYTHON=1
# Needs root (chroot, mounts). Exit status: ctest's; 125 (skip) when Debian's archive cannot be
# reached to make the root.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cache="${TRC_DEBIAN13_DIR:-$here/build/debian13}"
root="$cache/root"
mirror="${TRC_DEBIAN_MIRROR:-http://deb.debian.org/debian}"

say() { echo "test-debian13: $*"; }

. "$here/Module/debian-release.sh"
trc_release_for 13
packages=("${trc_packages[@]}")
mode=test
case "${1:-}" in
  --shell) mode=shell; shift ;;
  --bundle) mode=bundle; shift ;;
esac
stamp="trixie ${packages[*]}"

if [ "$(id -u)" -ne 0 ]; then
  say "needs root (chroot and mounts); skipped"
  exit 125
fi

# --- The root ----------------------------------------------------------------------------------
if [ ! -f "$root/.trc-complete" ] || [ "$(cat "$root/.trc-complete")" != "$stamp" ]; then
  if [ -d "$root" ]; then
    say "the cached root is incomplete or for other packages: made again"
    rm -rf "$root"
  fi
  if ! command -v mmdebstrap > /dev/null; then
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -q > /dev/null && apt-get install -y -q mmdebstrap > /dev/null ||
      { say "cannot install mmdebstrap (no network?); skipped"; exit 125; }
  fi
  mkdir -p "$cache"
  include="$(IFS=,; echo "${packages[*]}")"
  say "making a Debian 13 root in $root"
  if ! mmdebstrap --quiet --variant=apt --include="$include" trixie "$root" "$mirror"; then
    rm -rf "$root"
    say "cannot make the Debian 13 root from $mirror (no network?); skipped"
    exit 125
  fi
  echo "$stamp" > "$root/.trc-complete"
fi

# --- Build and test inside it ------------------------------------------------------------------
mkdir -p "$root/src" "$root/build"
mounted=()
cleanup() {
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    umount "${mounted[$i]}" 2> /dev/null || umount -l "${mounted[$i]}" || true
  done
}
trap cleanup EXIT
mount --bind "$here" "$root/src" && mounted+=("$root/src")
mount -o remount,bind,ro "$root/src" || true
mount --bind /dev "$root/dev" && mounted+=("$root/dev")
mount -t proc proc "$root/proc" && mounted+=("$root/proc")
# Open MPI 5's hwloc reads the CPU topology there; without it mpirun crashes (the MPI tests).
mount --bind /sys "$root/sys" && mounted+=("$root/sys")
# The name server for apt-get inside (the ParaView fetch).
[ -e "$root/etc/resolv.conf" ] || touch "$root/etc/resolv.conf"
mount --bind /etc/resolv.conf "$root/etc/resolv.conf" && mounted+=("$root/etc/resolv.conf")

if [ "$mode" = shell ]; then
  chroot "$root" /usr/bin/env -u DISPLAY bash -l || true
  exit 0
fi
if [ "$mode" = bundle ]; then
  [ -f "$root/build/CTestTestfile.cmake" ] || { say "no build in the root: run make test-debian13 first"; exit 1; }
  mkdir -p "$here/.bundle/debian13" "$root/bundle"
  mount --bind "$here/.bundle/debian13" "$root/bundle" && mounted+=("$root/bundle")
  # Without Python unless TRC_BUNDLE_PYTHON=1: the C++ tests (the mapper's among them) and the
  # benchmark programs, in 26 MiB rather than 38 (docs/testing.md, "Debian 13").
  no_python=1
  [ -n "${TRC_BUNDLE_PYTHON:-}" ] && no_python=""
  chroot "$root" /usr/bin/env -u DISPLAY TRC_BUILD_DIR=/build TRC_BUNDLE_OUT=/bundle \
    TRC_BUNDLE_NO_PYTHON="$no_python" TRC_BUNDLE_PY_MODULES="${TRC_BUNDLE_PY_MODULES:-}" \
    TRC_GIT_COMMIT="$(git -C "$here" rev-parse HEAD 2> /dev/null || echo unknown)" \
    /src/Module/bundle-gpu.sh
  exit 0
fi

ctest_args=""
for a in "$@"; do
  ctest_args+=" $(printf '%q' "$a")"
done
chroot "$root" /usr/bin/env -u DISPLAY bash -c "
  set -euo pipefail
  vtk=\$(dpkg-query -W -f='\${Version}' libvtk9-dev)
  echo \"test-debian13: Debian \$(cat /etc/debian_version), VTK \$vtk\"
  if [ ! -f /build/build.ninja ]; then
    cmake -S /src -B /build -G Ninja -Wno-dev -DCMAKE_BUILD_TYPE=Release \
      -DPython3_EXECUTABLE=/usr/bin/python3 -DTILEDRAYCAST_ENABLE_TETGEN=ON \
      -DTILEDRAYCAST_REPORT_OPENGL_ERRORS=ON > /build/configure.log
  fi
  cmake --build /build -j \$(nproc)
  cd /build
  ctest --output-on-failure $ctest_args
"
