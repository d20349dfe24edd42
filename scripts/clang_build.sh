#!/usr/bin/env bash
# Builds every module and its tests with Debian's clang into ./build-clang, warnings as errors, with the portable
# page_memory seam (engine/core/page_memory.h) instead of the Linux one, and runs those tests but the web page's
# (label web, which the gcc build runs); extra arguments go to ctest. --configure-only stops after configuring
# (scripts/tidy_check.sh needs only build-clang/compile_commands.json). CI runs it (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/setup_clang.sh
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build-clang -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS=-Werror \
  "${launcher[@]}" -DMESHEDIT_PAGE_MEMORY=portable -DMESHEDIT_BENCH_PEERS=OFF
if [ "${1:-}" = "--configure-only" ]; then exit 0; fi
cmake --build build-clang -j "$(nproc)"
ctest --test-dir build-clang --output-on-failure -j "$(nproc)" -LE web "$@"
