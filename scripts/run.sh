#!/usr/bin/env bash
# The README's first command: set up, build, and run meshedit (arguments are passed on).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh meshedit
exec ./build/meshedit "$@"
