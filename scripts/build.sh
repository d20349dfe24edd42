#!/usr/bin/env bash
# Sets up the packages (scripts/setup.sh), then configures and builds MeshEdit into ./build.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE="${MESHEDIT_BUILD_TYPE:-RelWithDebInfo}"
cmake --build build -j "$(nproc)"
