#!/usr/bin/env bash
# Runs the TiledRayCast test suite and an example on a GPU machine that has NVIDIA drivers but no
# Debian packages, from the bundle that Module/bundle-gpu.sh made (.bundle/tiledraycast-gpu.tar.xz).
# Run it from the repository root there:
#
#   Module/run-on-gpu.sh [ctest arguments...]      e.g.  Module/run-on-gpu.sh -R Headless
#
# It unpacks the bundle, points the dynamic loader at the bundled libraries and glvnd at the
# NVIDIA EGL driver, makes the paths baked into the build resolve on this machine, prints the GPU
# that EGL gives, runs ctest (without the tests that need an X server: there is none), and renders
# Examples/Python/headless_render.py. Exit status: ctest's.
#
# Environment:
#   TRC_EGL_VENDOR_FILE  glvnd EGL vendor file (default: NVIDIA's, see below). With
#                        /usr/share/glvnd/egl_vendor.d/50_mesa.json this runs on Mesa, to try the
#                        bundle on a machine without a GPU.
#   OUT                  if set (the device tool sets it), images and logs are copied there.
#   TRC_SKIP_CTEST=1     set up only (no ctest, no example), then run TRC_THEN.
#   TRC_THEN             a command run last, in this environment (bundle libraries, EGL vendor,
#                        TRC_BUNDLE_ROOT = the unpacked bundle), e.g. Benchmarks/run_benchmarks.sh.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bundle="$repo/.bundle"
archive="$bundle/tiledraycast-gpu.tar.xz"
root="$bundle/tiledraycast-gpu"

say() { echo "run-on-gpu: $*"; }
die() {
  echo "run-on-gpu: $*" >&2
  exit 1
}

# --- Unpack ------------------------------------------------------------------------------------
[ -f "$archive" ] || die "no $archive: run Module/bundle-gpu.sh on the build machine first"
if [ ! -f "$root/MANIFEST" ] || [ "$archive" -nt "$root/MANIFEST" ]; then
  rm -rf "$root"
  say "unpacking $(du -h "$archive" | cut -f1) bundle"
  if command -v xz > /dev/null; then
    tar -C "$bundle" -xJf "$archive"
  else
    # No xz here: Python's tarfile reads .tar.xz too.
    python3 -c 'import sys, tarfile; tarfile.open(sys.argv[1]).extractall(sys.argv[2])' \
      "$archive" "$bundle"
  fi
  touch "$root/MANIFEST"
fi
# shellcheck disable=SC1091
. "$root/MANIFEST"

# --- The C and C++ runtimes --------------------------------------------------------------------
# glibc is the machine's own (it comes with the dynamic loader): it must be recent enough.
glibc="$(getconf GNU_LIBC_VERSION 2> /dev/null | awk '{print $2}')"
if [ -n "$glibc" ] && [ "$(printf '%s\n%s\n' "$TRC_GLIBC_NEEDED" "$glibc" | sort -V | head -n 1)" != "$TRC_GLIBC_NEEDED" ]; then
  die "this machine has glibc $glibc; the bundle needs $TRC_GLIBC_NEEDED or later"
fi
# The bundle carries Debian's libstdc++ (GCC 12). If the machine's own is newer, it serves our
# programs as well and is what the machine's other libraries expect: use it instead.
newest_glibcxx() { grep -aoE 'GLIBCXX_3\.4\.[0-9]+' "$1" | sort -uV | tail -n 1; }
system_cxx="$( (ldconfig -p 2> /dev/null || true) | awk '$1 == "libstdc++.so.6" && /x86-64/ { print $NF; exit }')"
if [ -n "$system_cxx" ] && [ -f "$root/lib/libstdc++.so.6" ]; then
  mine="$(newest_glibcxx "$root/lib/libstdc++.so.6")"
  theirs="$(newest_glibcxx "$system_cxx")"
  if [ "$mine" != "$theirs" ] && [ "$(printf '%s\n%s\n' "$mine" "$theirs" | sort -V | tail -n 1)" = "$theirs" ]; then
    say "using this machine's newer libstdc++ ($system_cxx: $theirs)"
    mkdir -p "$root/lib-unused"
    mv "$root/lib/libstdc++.so.6" "$root/lib/libgcc_s.so.1" "$root/lib-unused/" 2> /dev/null || true
  fi
fi

# --- Loader, glvnd, Python ---------------------------------------------------------------------
library_path="$root/lib:$root/build/lib"
for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib /usr/lib/x86_64-linux-gnu/nvidia; do
  [ -d "$d" ] && library_path="$library_path:$d"
done
export LD_LIBRARY_PATH="$library_path${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"

vendor="${TRC_EGL_VENDOR_FILE:-/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json}"
if [ ! -f "$vendor" ]; then
  for candidate in /usr/share/glvnd/egl_vendor.d/10_nvidia.json /etc/glvnd/egl_vendor.d/10_nvidia.json; do
    if [ -f "$candidate" ]; then
      vendor="$candidate"
      break
    fi
  done
fi
[ -f "$vendor" ] || die "no glvnd EGL vendor file at $vendor (set TRC_EGL_VENDOR_FILE)"
export __EGL_VENDOR_LIBRARY_FILENAMES="$vendor"
say "glvnd EGL vendor: $vendor ($(tr -d ' \n' < "$vendor" | grep -oE '"library_path":"[^"]*"' || true))"

# No X server here: every window is the EGL one.
unset DISPLAY
python_exe="$root/py/bin/python$TRC_PYTHON_VERSION"
if [ "$TRC_PYTHON" = 1 ]; then
  export PYTHONHOME="$root/py"
  export PYTHONDONTWRITEBYTECODE=1
else
  # Python was left out of the bundle: the Python tests report "skipped" (code 125).
  python_exe="$root/bin/python-not-bundled"
  cat > "$python_exe" << 'EOF'
#!/bin/sh
echo "skipped: Debian's Python 3.11 is not in this bundle (Module/bundle-gpu.sh, TRC_BUNDLE_NO_PYTHON)"
exit 125
EOF
  chmod +x "$python_exe"
fi

# --- Paths baked into the build ----------------------------------------------------------------
# ctest files name the build and source directories of the build machine and Debian's
# /usr/bin/python3: point them at this checkout, the unpacked build tree and the bundled Python.
if [ ! -f "$root/.paths-rewritten" ]; then
  find "$root/build" \( -name CTestTestfile.cmake -o -name DartConfiguration.tcl \) -print0 | xargs -0 sed -i \
    -e "s#$TRC_BUILD_DIR#$root/build#g" \
    -e "s#$TRC_SOURCE_DIR#$repo#g" \
    -e "s#/usr/bin/python3\\([\" ]\\)#$python_exe\\1#g"
  touch "$root/.paths-rewritten"
fi
# Anything else that kept an absolute path (RPATHs, compiled-in defaults) finds the tree through
# links at the old places, where they can be made.
link_old_path() {
  local old="$1" new="$2"
  if [ "$old" != "$new" ] && [ ! -e "$old" ] && mkdir -p "$(dirname "$old")" 2> /dev/null; then
    ln -s "$new" "$old" 2> /dev/null && say "linked $old -> $new" || true
  fi
}
link_old_path "$TRC_SOURCE_DIR" "$repo"
case "$TRC_BUILD_DIR" in
  "$TRC_SOURCE_DIR"/*) [ -e "$repo/${TRC_BUILD_DIR#"$TRC_SOURCE_DIR"/}" ] ||
    ln -s "$root/build" "$repo/${TRC_BUILD_DIR#"$TRC_SOURCE_DIR"/}" 2> /dev/null || true ;;
  *) link_old_path "$TRC_BUILD_DIR" "$root/build" ;;
esac
mkdir -p "$root/build/Testing/Temporary"

# --- What EGL gives ----------------------------------------------------------------------------
say "bundle of commit $TRC_GIT_COMMIT, made $TRC_CREATED"
say "the EGL window on this machine:"
"$root/build/bin/TiledRayCastHeadlessCxxTests" TestHeadlessEGLWindow \
  -T "$root/build/Testing/Temporary" -V "$repo/Headless/Testing/Data/Baseline/TestHeadlessEGLWindow.png" 2>&1 |
  grep -E '^(EGL|OpenGL (vendor|renderer|version)|[0-9]+: |Mesa surfaceless)|rror' | grep -v Dart |
  sort -u | sed 's/^/  /' || true

# --- The suite ---------------------------------------------------------------------------------
status=0
if [ "${TRC_SKIP_CTEST:-0}" != 1 ]; then
say "ctest (the tests labelled X need an X server and are left out)"
set +e
(cd "$root/build" && "$root/bin/ctest" --output-on-failure -LE '^X$' "$@")
status=$?
set -e
fi

# --- An example --------------------------------------------------------------------------------
if [ "$TRC_PYTHON" = 1 ] && [ "${TRC_SKIP_CTEST:-0}" != 1 ]; then
  say "Examples/Python/headless_render.py"
  PYTHONPATH="$root/build/lib/python3/dist-packages" "$python_exe" \
    "$repo/Examples/Python/headless_render.py" --output "$bundle/headless_render.png" || status=1
fi

if [ -n "${OUT:-}" ] && [ -d "${OUT:-}" ]; then
  cp "$root"/build/Testing/Temporary/*.png "$root"/build/Testing/Temporary/LastTest*.log "$OUT"/ 2> /dev/null || true
  cp "$bundle/headless_render.png" "$OUT"/ 2> /dev/null || true
fi
if [ -n "${TRC_THEN:-}" ]; then
  export TRC_BUNDLE_ROOT="$root" TRC_PYTHON_EXE="$python_exe"
  say "running: $TRC_THEN"
  (cd "$repo" && eval "$TRC_THEN") || status=1
fi
say "done: exit status $status"
exit "$status"
