#!/usr/bin/env bash
# make sanitize: builds TiledRayCast with AddressSanitizer and UndefinedBehaviorSanitizer in
# ./build-asan (or $TRC_ASAN_BUILD_DIR) and runs the C++ and Python tests under them. Assertions
# stay on (no NDEBUG) at -O1, so that the tests' CPU reference renderers keep a usable speed.
# Extra arguments go to ctest (e.g. -R Python).
#
# Python tests: /usr/bin/python3 is not instrumented, so the ASan runtime is preloaded into it
# (TILEDRAYCAST_PYTHON_TEST_PRELOAD, set below, puts LD_PRELOAD on the Python tests only).
# Leaks are not checked (detect_leaks=0): Mesa, Python and VTK's singletons hold memory at exit
# that is not ours. UBSan stops at the first error with a stack trace.
# TiledRayCast-DownstreamExample is left out: it builds Examples/Cxx against the installed build
# without the sanitizer flags, which an instrumented library refuses to be loaded into. So are
# the ParaView tests (label ParaView): ParaView's programs are not instrumented and the plugin they
# load is built apart, without the sanitizers (its Debug build runs in make test); their Python
# driver, loading this instrumented build, aborted ("ASan runtime does not come first").
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TRC_ASAN_BUILD_DIR:-$here/build-asan}"

"$here/Module/install-deps.sh"

libasan="$(g++ -print-file-name=libasan.so)"
if [ ! -e "$libasan" ]; then
  echo "error: the AddressSanitizer runtime (libasan.so, from g++'s libgcc-*-dev) is missing" >&2
  exit 1
fi
sanitize="-fsanitize=address,undefined -fno-omit-frame-pointer"

start=$(date +%s)
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$here" -B "$build" -G Ninja \
    -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_C_FLAGS_DEBUG="-g -O1" \
    -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" \
    -DCMAKE_C_FLAGS="$sanitize" \
    -DCMAKE_CXX_FLAGS="$sanitize" \
    -DCMAKE_EXE_LINKER_FLAGS="$sanitize" \
    -DCMAKE_SHARED_LINKER_FLAGS="$sanitize" \
    -DCMAKE_MODULE_LINKER_FLAGS="$sanitize" \
    -DPython3_EXECUTABLE=/usr/bin/python3 \
    -DTILEDRAYCAST_ENABLE_TETGEN=ON \
    -DTILEDRAYCAST_PYTHON_TEST_PRELOAD="$libasan"
fi
cmake --build "$build" -j "$(nproc)"
built=$(date +%s)

cd "$build"
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
status=0
echo "make sanitize: TiledRayCast-DownstreamExample and the ParaView tests are left out (not instrumented)"
env -u DISPLAY ctest --output-on-failure -j "$(nproc)" -E '^TiledRayCast-DownstreamExample$' \
  -LE ParaView "$@" || status=$?
end=$(date +%s)
echo "make sanitize: build $((built - start)) s, tests $((end - built)) s"
exit $status
