#!/usr/bin/env bash
# Packs what the test suite and the examples need at run time on a GPU machine that has NVIDIA
# drivers but no Debian packages, into .bundle/tiledraycast-gpu.tar.xz (under 64 MiB), for
# Module/run-on-gpu.sh to unpack and run there. See docs/headless.md.
#
# What goes in (tiledraycast-gpu/ inside the archive):
#   build/   the build tree without object files: test drivers, benchmark and example programs,
#            our libraries and Python package, every CTestTestfile.cmake
#   lib/     every shared library those programs load (the ldd closure), plus glvnd's dispatch
#            libraries (libEGL.so.1, libGLdispatch.so.0, libOpenGL.so.0, libGLX.so.0, libGL.so.1),
#            but no driver (Mesa's or NVIDIA's: glvnd loads the machine's own) and nothing of
#            glibc (it must be the machine's, the dynamic loader included)
#   py/      Debian's python3 (3.11 on Debian 12, 3.13 on Debian 13) with its standard library and
#            the vtkmodules the tests import (the machine's python3.12 cannot load Debian's
#            extension modules)
#   bin/     ctest, with the one CMake file it looks for
#   MANIFEST where the build was made, and what the libraries need from glibc and libstdc++
#
# Usage: Module/bundle-gpu.sh            (after Module/build.sh; TRC_BUILD_DIR as for build.sh)
#        TRC_BUNDLE_OUT=DIR ...          write DIR/tiledraycast-gpu.tar.xz (default .bundle)
#        make test-debian13 ARGS=--bundle is the Debian 13 build's bundle: this script run inside
#        the Debian 13 root (Module/test-debian13.sh --bundle), into .bundle/debian13/
#        TRC_BUNDLE_NO_PYTHON=1 ...      leave Python out (its tests then skip with code 125)
#        TRC_BUNDLE_PY_MODULES="vtkIOExodus ..."  more vtkmodules to include
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TRC_BUILD_DIR:-$here/build}"
out="${TRC_BUNDLE_OUT:-$here/.bundle}"
budget=$((64 * 1024 * 1024))
. "$here/Module/debian-release.sh"
trc_release_or_die
python_version="$trc_python"
python_exe="/usr/bin/python$python_version"
vtk_version="$trc_vtk"
vtkmodules_dir=/usr/lib/python3/dist-packages/vtkmodules

die() {
  echo "bundle-gpu: $*" >&2
  exit 1
}

[ -f "$build/CTestTestfile.cmake" ] || die "no build in $build: run Module/build.sh first"
source_dir="$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")"
build_dir="$(cd "$build" && pwd -P)"
[ -n "$source_dir" ] || die "cannot read CMAKE_HOME_DIRECTORY from $build/CMakeCache.txt"

stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
root="$stage/tiledraycast-gpu"
mkdir -p "$root/build" "$root/lib" "$root/bin"

# --- 1. The build tree, without objects --------------------------------------------------------
(
  cd "$build"
  # Not the Debian 13 root that make test-debian13 keeps here (another build, other libraries).
  find . \( -name CMakeFiles -o -path ./debian13 \) -prune -o -name CTestTestfile.cmake -print
  [ -f DartConfiguration.tcl ] && echo ./DartConfiguration.tcl
  [ -d bin ] && find bin -type f
  # The benchmark programs (docs/benchmarks.md), which the GPU runs too.
  [ -d Benchmarks ] && find Benchmarks -maxdepth 1 -type f -perm -u+x
  find lib \( -type f -o -type l \) \( -name '*.so*' -o -name '*.py' -o -name '*.cmake' \)
) | tar -C "$build" -cf - -T - | tar -C "$root/build" -xf -
mkdir -p "$root/build/Testing/Temporary"

# --- 2. Python ---------------------------------------------------------------------------------
with_python=1
if [ -n "${TRC_BUNDLE_NO_PYTHON:-}" ] || [ ! -x "$python_exe" ] || [ ! -d "$vtkmodules_dir" ]; then
  with_python=0
fi
if [ "$with_python" = 1 ]; then
  py="$root/py"
  mkdir -p "$py/bin" "$py/lib/python3/dist-packages/vtkmodules"
  cp -L "$python_exe" "$py/bin/python$python_version"
  # The standard library, less what tests never use: GUI and test packages, and the extension
  # modules that would drag in large libraries (Berkeley DB, SQLite, OpenSSL's TLS, ncurses);
  # also sitecustomize.py, a link into /etc.
  tar -C /usr/lib -cf - \
    --exclude="python$python_version/test" --exclude="python$python_version/idlelib" \
    --exclude="python$python_version/tkinter" --exclude="python$python_version/turtledemo" \
    --exclude="python$python_version/ensurepip" --exclude="python$python_version/lib2to3" \
    --exclude="python$python_version/pydoc_data" --exclude="python$python_version/config-*" \
    --exclude="python$python_version/sitecustomize.py" --exclude='__pycache__' \
    --exclude='_dbm.*' --exclude='_gdbm.*' --exclude='_sqlite3.*' --exclude='_curses*' \
    --exclude='readline.*' --exclude='_tkinter.*' --exclude='_ssl.*' --exclude='sqlite3' \
    --exclude='dbm' --exclude='curses' \
    "python$python_version" | tar -C "$py/lib" -xf -
  # vtkmodules: the pure-Python parts that tests use, and one extension module per VTK library
  # the C++ side loads, plus any module a Python test or example names.
  cp "$vtkmodules_dir/__init__.py" "$py/lib/python3/dist-packages/vtkmodules/"
  for d in util test; do
    [ -d "$vtkmodules_dir/$d" ] &&
      tar -C "$vtkmodules_dir" -cf - --exclude='__pycache__' "$d" |
      tar -C "$py/lib/python3/dist-packages/vtkmodules" -xf -
  done
fi

# The ldd closure of a list of ELF files: prints "soname path" for every library outside glibc and
# outside the build tree.
closure() {
  local f
  for f in "$@"; do
    ldd "$f" 2>/dev/null | awk '$2 == "=>" && $3 ~ /^\// { print $1, $3 }'
  done | sort -u | while read -r name path; do
    case "$name" in
      ld-linux*.so* | libc.so.* | libm.so.* | libdl.so.* | libpthread.so.* | librt.so.* | \
        libresolv.so.* | libutil.so.* | libanl.so.* | libmvec.so.* | libBrokenLocale.so.*)
        continue ;;
    esac
    case "$(readlink -f "$path")" in
      "$build_dir"/* | "$root"/*) continue ;;
    esac
    echo "$name $path"
  done
}

elf_files() {
  find "$@" -type f 2>/dev/null | while read -r f; do
    if head -c 4 "$f" 2>/dev/null | grep 'ELF' > /dev/null; then echo "$f"; fi
  done
}

if [ "$with_python" = 1 ]; then
  mapfile -t cxx_elfs < <(elf_files "$root/build")
  wanted=""
  for lib in $(closure "${cxx_elfs[@]}" | awk '{print $1}'); do
    case "$lib" in
      libvtk*-"$vtk_version".so*) wanted+=" $(echo "$lib" | sed -E 's/^lib(vtk[A-Za-z0-9]+)-[0-9]+\.[0-9]+\.so.*/\1/')" ;;
    esac
  done
  # (each module's tests are in its folder's Testing/Python; the package's in Testing/Python)
  wanted+=" $({ cat "$here"/Testing/Python/*.py "$here"/*/Testing/Python/*.py \
    "$here"/Examples/Python/*.py 2>/dev/null || true; } |
    { grep -oE 'vtkmodules\.vtk[A-Za-z0-9]+' || true; } | sed 's/^vtkmodules\.//' | sort -u | tr '\n' ' ')"
  wanted+=" vtkCommonCore vtkRenderingCore vtkRenderingOpenGL2 vtkTestingRendering"
  wanted+=" ${TRC_BUNDLE_PY_MODULES:-}"
  for m in $(echo "$wanted" | tr ' ' '\n' | sort -u); do
    f="$vtkmodules_dir/$m.cpython-${python_version/./}-x86_64-linux-gnu.so"
    [ -f "$f" ] && cp "$f" "$py/lib/python3/dist-packages/vtkmodules/"
  done
fi

# --- 3. ctest -----------------------------------------------------------------------------------
ctest_exe="$(command -v ctest)" || die "ctest not found"
cmake_root="/usr/share/cmake-$(ctest --version | sed -n 1p | grep -oE "[0-9]+\.[0-9]+" | sed -n 1p)"
[ -f "$cmake_root/Modules/CMake.cmake" ] || die "cannot find CMake's modules ($cmake_root)"
cp -L "$ctest_exe" "$root/bin/ctest"
# ctest only checks that <prefix>/share/cmake-3.x/Modules/CMake.cmake exists next to itself.
mkdir -p "$root/share/$(basename "$cmake_root")/Modules"
cp "$cmake_root/Modules/CMake.cmake" "$root/share/$(basename "$cmake_root")/Modules/"

# --- 4. Shared libraries ------------------------------------------------------------------------
glvnd=(libEGL.so.1 libGLdispatch.so.0 libOpenGL.so.0 libGLX.so.0 libGL.so.1)
for name in "${glvnd[@]}"; do
  path="$(ldconfig -p | awk -v n="$name" '$1 == n && /x86-64/ && !found { print $NF; found = 1 }')"
  [ -n "$path" ] || die "glvnd library $name not found (install libglvnd0, libegl1, libgl1)"
  cp -L "$path" "$root/lib/$name"
done
mapfile -t all_elfs < <(elf_files "$root/build" "$root/py" "$root/bin" "$root/lib")
closure "${all_elfs[@]}" | while read -r name path; do
  [ -e "$root/lib/$name" ] || cp -L "$path" "$root/lib/$name"
done
# Drivers are the machine's: none may have slipped in.
for f in "$root"/lib/*; do
  case "$(basename "$f")" in
    libEGL_* | libGLX_mesa* | libgallium* | libLLVM* | libnvidia* | libcuda* | *_dri.so | libglapi*)
      die "a driver library slipped into the bundle: $f" ;;
  esac
done

# --- 5. Manifest --------------------------------------------------------------------------------
mapfile -t all_elfs < <(elf_files "$root")
max_version() { # highest <prefix>N.N.N symbol version that the files need
  objdump -T "${all_elfs[@]}" 2>/dev/null | grep -oE "\(?$1[0-9.]+" | tr -d '(' |
    sed "s/^$1//" | sort -t. -k1,1n -k2,2n -k3,3n -u | tail -n 1
}
{
  echo "TRC_BUILD_DIR=$build_dir"
  echo "TRC_SOURCE_DIR=$source_dir"
  echo "TRC_GLIBC_NEEDED=$(max_version GLIBC_)"
  echo "TRC_GLIBCXX_NEEDED=$(max_version GLIBCXX_)"
  echo "TRC_PYTHON=$with_python"
  echo "TRC_PYTHON_VERSION=$python_version"
  echo "TRC_DEBIAN=$trc_debian"
  echo "TRC_VTK=$vtk_version"
  echo "TRC_GIT_COMMIT=${TRC_GIT_COMMIT:-$(git -C "$here" rev-parse HEAD 2>/dev/null || echo unknown)}"
  echo "TRC_CREATED=$(date -u +%Y-%m-%dT%H:%M:%SZ)"
} > "$root/MANIFEST"

# --- 6. Archive ---------------------------------------------------------------------------------
mkdir -p "$out"
rm -rf "$out/tiledraycast-gpu" "$out/tiledraycast-gpu.tar.xz"
tar -C "$stage" -cf - tiledraycast-gpu | xz -T2 -9 > "$out/tiledraycast-gpu.tar.xz"
size=$(stat -c %s "$out/tiledraycast-gpu.tar.xz")
unpacked=$(du -sb "$root" | cut -f1)
awk -v f="$out/tiledraycast-gpu.tar.xz" -v s="$size" -v u="$unpacked" \
  -v n="$(ls "$root/lib" | wc -l)" -v p="$([ "$with_python" = 1 ] && echo included || echo 'left out')" \
  'BEGIN { printf "bundle-gpu: %s: %.1f MiB (%.1f MiB unpacked; %d libraries; Python %s)\n", f, s / 1048576, u / 1048576, n, p }'

if [ "$size" -gt "$budget" ]; then
  die "the bundle is over 64 MiB: try TRC_BUNDLE_NO_PYTHON=1"
fi
