#!/usr/bin/env bash
# Runs clang-tidy with the checks of .clang-tidy over every module of engine/ (their .cpp files and the headers they
# include) and fails on any finding. Uses the clang build's compile commands
# (build-clang/compile_commands.json, configured here if missing); needs nothing built. CI runs it (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup_clang.sh
[ -f build-clang/compile_commands.json ] || ./scripts/clang_build.sh --configure-only
log=build-clang/tidy.log
status=0
files="/engine/[a-z]+/.*\.cpp$"
run-clang-tidy -p build-clang -j "$(nproc)" -quiet "$files" > "$log" 2>&1 || status=$?
grep -v '^clang-tidy' "$log" || true  # the findings, without the command line of every file
if [ "$status" -ne 0 ]; then
  echo "tidy_check: clang-tidy found something (above; the whole output is in $log)" >&2
  exit 1
fi
echo "tidy_check: no finding in engine/ ($(grep -c '^clang-tidy' "$log") files)"
