#!/usr/bin/env bash
# Holds the window's headers (engine/app/*.h) to at most 200 lines each: a header past that holds more than one job,
# and the state it owns belongs in a room of its own (docs/ARCHITECTURE.md, engine/app/editor_app.h). Prints each
# header over the limit with its length and fails. CTest runs it (header_size_check), so CI does.
set -euo pipefail
cd "$(dirname "$0")/.."

readonly limit=200
status=0
for header in engine/app/*.h; do
  lines=$(wc -l < "$header")
  if [ "$lines" -gt "$limit" ]; then
    echo "$header: $lines lines, over the $limit a header of engine/app may have: give its state a room"
    status=1
  fi
done
if [ "$status" -eq 0 ]; then
  echo "header_size_check: every header in engine/app has at most $limit lines"
fi
exit "$status"
