#!/usr/bin/env bash
# Packs what ParaView's ranks need on a GPU machine that has NVIDIA's driver but no Debian
# packages and no X server: pvbatch and pvserver from the private ParaView root (5.11 on Debian 12), every
# library they and the plugin load (the ldd closure, glibc and the GPU driver left out), ParaView's
# Python packages and the standard library of the Python pvbatch embeds (3.11), Open MPI's mpirun with its
# components, and the plugin (Release, `make paraview`). The whole is far over what one device
# call carries (64 MiB with the repository), so its .tar.xz is cut into byte parts under
# .bundle/paraview-gpu/ (part-00.xz, ...), carried by successive calls to a machine that stays
# warm between them; ParaView/run-on-gpu.sh keeps each and unpacks the whole once the last has
# come (docs/parallel.md).
#
# Usage: ParaView/bundle-gpu.sh [part size in MiB, default 38: 64 less the repository and room]   (after `make paraview`)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TRC_BUILD_DIR:-$here/build}"
pvroot="${TRC_PARAVIEW_ROOT:-$build/paraview/root}"
# shellcheck source=../Module/debian-release.sh
. "$here/Module/debian-release.sh"
trc_release_or_die
py="python$trc_python"
plugin_dir="$build/paraview/plugin/lib/paraview-$trc_paraview/plugins/TiledRayCast"
out="$here/.bundle/paraview-gpu"
part_size=$((${1:-38} * 1024 * 1024))
arch=x86_64-linux-gnu

die() {
  echo "bundle-gpu (ParaView): $*" >&2
  exit 1
}
[ -x "$pvroot/usr/bin/pvbatch" ] || die "no private ParaView root in $pvroot: run make paraview"
[ -f "$plugin_dir/TiledRayCast.so" ] || die "no Release plugin in $plugin_dir: run make paraview"
command -v orterun > /dev/null ||
  die "no orterun: Debian 12's Open MPI 4 is what this bundle relocates (Debian 13's Open MPI 5 \
starts its ranks through PRRTE, not packed here yet); make the ParaView GPU bundle on Debian 12"

stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
root="$stage/pv"
mkdir -p "$root/bin" "$root/lib" "$root/plugin" "$root/python/lib" "$root/python/dist-packages"

# --- Programs, plugin, Python --------------------------------------------------------------------
for p in pvbatch pvserver pvpython; do
  cp -L "$pvroot/usr/bin/$p" "$root/bin/"
done
cp -L "$(command -v orterun)" "$root/bin/orterun"
cp -L "$(command -v orted)" "$root/bin/orted"
cp -a "$plugin_dir/." "$root/plugin/"
# ParaView's Python packages (paraview, vtkmodules: ParaView's VTK, not Debian's 9.1).
tar -C "$pvroot/usr/lib/python3/dist-packages" -cf - --exclude='__pycache__' --exclude='tests' \
  paraview vtkmodules vtk.py | tar -C "$root/python/dist-packages" -xf -
# The standard library of the Python pvbatch embeds (Debian's 3.11), less what ranks never use.
tar -C /usr/lib -cf - --exclude="$py/test" --exclude="$py/idlelib" \
  --exclude="$py/tkinter" --exclude="$py/turtledemo" \
  --exclude="$py/ensurepip" --exclude="$py/lib2to3" \
  --exclude="$py/pydoc_data" --exclude="$py/config-*" \
  --exclude="$py/sitecustomize.py" --exclude='__pycache__' --exclude="$py/dist-packages" \
  "$py" | tar -C "$root/python/lib" -xf -

# --- Open MPI, relocated by OPAL_PREFIX (run-on-gpu.sh) ------------------------------------------
mkdir -p "$root/openmpi/lib/$arch" "$root/openmpi/share" "$root/openmpi/etc"
cp -a "/usr/lib/$arch/openmpi" "$root/openmpi/lib/$arch/"
cp -a /usr/share/openmpi "$root/openmpi/share/"
cp -a /etc/openmpi "$root/openmpi/etc/"
for d in "/usr/lib/$arch/pmix2" "/usr/share/pmix"; do
  [ -d "$d" ] && mkdir -p "$root/openmpi$(dirname "$d")" && cp -a "$d" "$root/openmpi$(dirname "$d")/"
done

# --- Libraries: the ldd closure of every ELF file, with ParaView's root on the path -------------
export LD_LIBRARY_PATH="$pvroot/usr/lib/$arch:$plugin_dir"
find "$root" -type f \( -name '*.so*' -o -perm -u+x \) | while read -r f; do
  head -c 4 "$f" 2> /dev/null | grep -q ELF && ldd "$f" 2> /dev/null || true
done | awk '$2 == "=>" && $3 ~ /^\// { print $1, $3 }' | sort -u | while read -r name path; do
  case "$name" in
    ld-linux*.so* | libc.so.* | libm.so.* | libdl.so.* | libpthread.so.* | librt.so.* | \
      libresolv.so.* | libutil.so.* | libanl.so.* | libmvec.so.* | libBrokenLocale.so.*) continue ;;
    libEGL_* | libGLX_mesa* | libgallium* | libLLVM* | libnvidia* | libcuda* | libglapi*) continue ;;
  esac
  case "$(readlink -f "$path")" in "$plugin_dir"/* | "$root"/*) continue ;; esac
  [ -e "$root/lib/$name" ] || cp -L "$path" "$root/lib/$name"
done
# glvnd's dispatchers (the driver behind them is the machine's).
for name in libEGL.so.1 libGLdispatch.so.0 libOpenGL.so.0 libGLX.so.0 libGL.so.1; do
  path="$(ldconfig -p | awk -v n="$name" '$1 == n && /x86-64/ && !found { print $NF; found = 1 }')"
  [ -n "$path" ] && cp -L "$path" "$root/lib/$name"
done
objdump -T "$root"/lib/*.so* "$root"/bin/* 2> /dev/null | grep -oE 'GLIBC_[0-9.]+' |
  sed 's/GLIBC_//' | sort -t. -k1,1n -k2,2n -k3,3n -u | tail -n 1 > "$root/GLIBC_NEEDED"
git -C "$here" rev-parse HEAD > "$root/COMMIT" 2> /dev/null || echo unknown > "$root/COMMIT"

# --- One xz stream of the whole, cut into parts that each fit one call -------------------------
# Byte parts, not parts of whole files: every part but the last is exactly the size asked, so the
# fewest calls carry it. run-on-gpu.sh joins them once all have come.
rm -rf "$out"
mkdir -p "$out"
tar -C "$stage" -cf - pv | xz -T2 -6 | split -b "$part_size" -d -a 2 --additional-suffix=.xz - "$out/part-"
ls "$out"/part-*.xz | wc -l > "$out/PARTS"
ls -l "$out" | awk 'NR > 1 { printf "bundle-gpu (ParaView): %s %.1f MiB\n", $9, $5 / 1048576 }'
du -sh "$root" | awk '{ print "bundle-gpu (ParaView): " $1 " unpacked" }'
