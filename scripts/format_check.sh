#!/usr/bin/env bash
# Checks that every C++ file under engine/ and tests/ is formatted as .clang-format says (clang-format --dry-run
# -Werror) and fails naming the files that are not; with --fix, reformats them in place instead. CI runs it (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup_clang.sh >/dev/null
files=(engine tests)
list() { git ls-files -z -- "${files[@]/%//*.cpp}" "${files[@]/%//*.h}" "${files[@]/%//*.c}"; }
if [ "${1:-}" = "--fix" ]; then
  list | xargs -0 -P "$(nproc)" -n 16 clang-format -i
  exit 0
fi
report=$(list | xargs -0 -n 32 clang-format --dry-run -Werror 2>&1 |
  sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' | sort | uniq -c || true)
if [ -n "$report" ]; then
  echo "$report"
  echo "format_check: $(echo "$report" | wc -l) files differ from .clang-format ($(echo "$report" |
    awk '{n += $1} END {print n}') places); scripts/format_check.sh --fix reformats them"
  exit 1
fi
echo "format_check: every file under engine/ and tests/ is formatted"
