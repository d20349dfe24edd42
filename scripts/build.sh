#!/usr/bin/env bash
# Sets up the packages (scripts/setup.sh), then configures and builds MeshEdit into ./build.
# With arguments, builds only those targets (scripts/run.sh builds just `meshedit`).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE="${MESHEDIT_BUILD_TYPE:-RelWithDebInfo}"
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j "$(nproc)" "${targets[@]}"
