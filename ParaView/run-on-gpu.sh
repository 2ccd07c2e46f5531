#!/usr/bin/env bash
# Runs ParaView's pvbatch (and mpirun) with the plugin on a GPU machine without X or Debian
# packages, from the parts that ParaView/bundle-gpu.sh made (.bundle/paraview-gpu/part-NN.tar.xz).
#
#   ParaView/run-on-gpu.sh unpack           unpacks the parts present (the others may come in
#                                           later calls: each part is unpacked once, into
#                                           ${TRC_PV_GPU_DIR:-/tmp/trc-paraview-gpu})
#   ParaView/run-on-gpu.sh run COMMAND...   runs COMMAND with the unpacked ParaView in the
#                                           environment: pvbatch, pvserver, mpirun on PATH,
#                                           TRC_PV_PLUGIN the plugin, NVIDIA's EGL driver for
#                                           glvnd, no DISPLAY, Open MPI relocated (OPAL_PREFIX)
#
# Exit status: the command's; 1 when ParaView is not unpacked yet.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
parts_dir="$repo/.bundle/paraview-gpu"
dir="${TRC_PV_GPU_DIR:-/tmp/trc-paraview-gpu}"
say() { echo "run-on-gpu (ParaView): $*"; }
die() {
  echo "run-on-gpu (ParaView): $*" >&2
  exit 1
}

unpack() {
  mkdir -p "$dir/parts"
  local part
  for part in "$parts_dir"/part-*.xz; do
    [ -f "$part" ] || continue
    [ -f "$dir/parts/$(basename "$part")" ] && continue
    cp "$part" "$dir/parts/"
    say "kept $(basename "$part") ($(du -h "$part" | cut -f1))"
  done
  [ -f "$parts_dir/PARTS" ] && cp "$parts_dir/PARTS" "$dir/PARTS"
  [ -f "$dir/PARTS" ] || die "no part has come yet"
  [ -f "$dir/UNPACKED" ] && return
  local have
  have=$(ls "$dir/parts" | wc -l)
  if [ "$have" -lt "$(cat "$dir/PARTS")" ]; then
    say "$have of $(cat "$dir/PARTS") parts here: carry the others in the next calls"
    return
  fi
  if command -v xz > /dev/null; then
    cat "$dir/parts"/part-*.xz | xz -d -T0 | tar -C "$dir" -xf -
  else
    cat "$dir/parts"/part-*.xz | python3 -c 'import lzma, sys, tarfile
tarfile.open(fileobj=lzma.open(sys.stdin.buffer), mode="r|").extractall(sys.argv[1])' "$dir"
  fi
  rm -rf "$dir/parts"
  touch "$dir/UNPACKED"
  say "unpacked all $have parts into $dir ($(du -sh "$dir/pv" | cut -f1))"
}

environment() {
  local root="$dir/pv"
  [ -f "$dir/UNPACKED" ] || die "not unpacked yet: carry every part (ParaView/run-on-gpu.sh unpack)"
  local glibc needed
  glibc="$(getconf GNU_LIBC_VERSION | awk '{ print $2 }')"
  needed="$(cat "$root/GLIBC_NEEDED")"
  [ "$(printf '%s\n%s\n' "$needed" "$glibc" | sort -V | head -n 1)" = "$needed" ] ||
    die "this machine has glibc $glibc; ParaView's libraries need $needed"
  # The machine's libstdc++ where it is newer (the driver's libraries may need it).
  local system_cxx
  system_cxx="$( (ldconfig -p 2> /dev/null || true) | awk '$1 == "libstdc++.so.6" && /x86-64/ { print $NF; exit }')"
  if [ -n "$system_cxx" ] && [ -f "$root/lib/libstdc++.so.6" ]; then
    local mine theirs
    mine="$(grep -aoE 'GLIBCXX_3\.4\.[0-9]+' "$root/lib/libstdc++.so.6" | sort -uV | tail -n 1)"
    theirs="$(grep -aoE 'GLIBCXX_3\.4\.[0-9]+' "$system_cxx" | sort -uV | tail -n 1)"
    if [ "$(printf '%s\n%s\n' "$mine" "$theirs" | sort -V | tail -n 1)" = "$theirs" ] && [ "$mine" != "$theirs" ]; then
      mkdir -p "$root/lib-unused"
      mv "$root/lib/libstdc++.so.6" "$root/lib/libgcc_s.so.1" "$root/lib-unused/" 2> /dev/null || true
    fi
  fi
  local library_path="$root/lib:$root/plugin"
  local d
  for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib /usr/lib/x86_64-linux-gnu/nvidia; do
    [ -d "$d" ] && library_path="$library_path:$d"
  done
  export LD_LIBRARY_PATH="$library_path${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  local vendor="${TRC_EGL_VENDOR_FILE:-/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json}"
  for d in /usr/share/glvnd/egl_vendor.d/10_nvidia.json /etc/glvnd/egl_vendor.d/10_nvidia.json; do
    [ -f "$vendor" ] || vendor="$d"
  done
  [ -f "$vendor" ] && export __EGL_VENDOR_LIBRARY_FILENAMES="$vendor"
  unset DISPLAY
  export PYTHONHOME="$root/python" PYTHONPATH="$root/python/dist-packages" PYTHONDONTWRITEBYTECODE=1
  # pvbatch looks for its vtkmodules at lib/python3/dist-packages above its own directory, up to
  # /, and puts what it finds first: give it ParaView's here, before a Debian VTK's at /.
  mkdir -p "$root/lib/python3"
  ln -sfn ../../python/dist-packages "$root/lib/python3/dist-packages"
  # Open MPI where it was unpacked, not under /usr.
  export OPAL_PREFIX="$root/openmpi" OPAL_SYSCONFDIR="$root/openmpi/etc/openmpi"
  export OPAL_BINDIR="$root/bin" OPAL_LIBDIR="$root/openmpi/lib/x86_64-linux-gnu/openmpi/lib"
  export OPAL_PKGDATADIR="$root/openmpi/share/openmpi" OPAL_DATADIR="$root/openmpi/share"
  export PMIX_INSTALL_PREFIX="$root/openmpi" PMIX_MCA_mca_base_component_path="$root/openmpi/usr/lib/x86_64-linux-gnu/pmix2/lib/pmix"
  export OMPI_MCA_btl="self,vader" OMPI_MCA_btl_vader_single_copy_mechanism=none
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  # The machine may have a PMIx of its own whose plugins do not load into this one: quiet.
  export PMIX_MCA_mca_base_component_show_load_errors=0 PMIX_MCA_pcompress_base_silence_warning=1
  mkdir -p "$root/mpibin"
  ln -sf "$root/bin/orterun" "$root/mpibin/mpirun"
  export PATH="$root/bin:$root/mpibin:$PATH"
  export TRC_PV_PLUGIN="$root/plugin/TiledRayCast.so"
}

case "${1:-}" in
  unpack) unpack ;;
  run)
    shift
    environment
    exec "$@"
    ;;
  *) die "usage: $0 unpack | run COMMAND..." ;;
esac
