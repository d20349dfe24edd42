#!/usr/bin/env bash
# Builds MeshEdit with AddressSanitizer + UndefinedBehaviorSanitizer into ./build-asan (Debug) and runs every test
# there; extra arguments go to ctest (e.g. -R Window). Fails on a failed test or on any sanitizer report. Tests are
# tried twice, because the sanitizers make the code 2-3x slower and a few grading tests race a 0.5 s limit.
# From scratch on the 2-core machine: about 27 minutes to build (cold ccache), 5 to 13 to test (by machine load).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
sanitize="-fsanitize=address,undefined -fno-omit-frame-pointer"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug "${launcher[@]}" \
  -DCMAKE_CXX_FLAGS="$sanitize -fno-sanitize-recover=undefined" -DCMAKE_C_FLAGS="$sanitize" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined"
cmake --build build-asan -j "$(nproc)"

# Mesa's driver stays loaded so its blocks stay reachable (see tests/sanitizers/keep_libraries_loaded.c).
"${CC:-cc}" -shared -fPIC -o build-asan/keep_libraries_loaded.so tests/sanitizers/keep_libraries_loaded.c
export LD_PRELOAD="$PWD/build-asan/keep_libraries_loaded.so"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:verify_asan_link_order=0
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp"
export UBSAN_OPTIONS=print_stacktrace=1

log=build-asan/sanitize.log
status=0
ctest --test-dir build-asan --output-on-failure -j "$(nproc)" --repeat until-pass:2 "$@" 2>&1 | tee "$log" || status=$?
if grep -qE 'runtime error:|ERROR: (Address|Leak)Sanitizer' "$log"; then
  echo "sanitize.sh: a sanitizer reported a problem (see $log)" >&2
  exit 1
fi
exit "$status"
