#!/usr/bin/env bash
# web_writeup_match.sh MESHEDIT ACTIONS STUDENT_FILE=FIXTURE...: whether the web page's File > Write-up makes the
# write-up `meshedit writeup` makes for the same files. The files: the packaged templates of scripts/student/, each
# STUDENT_FILE replaced by the file FIXTURE. The desktop writes the write-up of a folder of those files with the native
# binary MESHEDIT; the page (scripts/web_test.sh, the start screen) has the fixtures dropped on it once ACTIONS has
# written /tmp/ready.json, plays ACTIONS (which makes the write-up) and downloads index.html;
# tests/web/compare_writeups.py then compares the two pages. Keeps NAME-desktop.html and NAME-page.html in
# build-web/test/. Exit status: 0 the same, 1 not (or a run failed), 77 skipped (web_test.sh's reasons).
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 3 ] || { echo "usage: web_writeup_match.sh MESHEDIT ACTIONS STUDENT_FILE=FIXTURE..."; exit 1; }
meshedit=$(realpath "$1")
actions=$2
shift 2
name=$(basename "$actions" .txt)
out=build-web/test
mkdir -p "$out"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# shellcheck source=scripts/web_student_fixtures.sh
source scripts/web_student_fixtures.sh
student_fixtures "$scratch" "$@"

status=0
"$meshedit" writeup --submission "$scratch/submission" -o "$scratch/desktop" >"$scratch/desktop.log" 2>&1 || status=$?
if [ "$status" -gt 1 ] || [ ! -f "$scratch/desktop/index.html" ]; then
  cat "$scratch/desktop.log"
  echo "web_writeup_match: meshedit writeup did not write the write-up"
  exit 1
fi
cp "$scratch/desktop/index.html" "$out/$name-desktop.html"

status=0
./scripts/web_test.sh "$actions" "" --ready /tmp/ready.json --drop "${dropped[@]}" --download index.html \
  --timeout 600 || status=$?
[ "$status" -eq 0 ] || exit "$status"
cp "$out/downloads/index.html" "$out/$name-page.html"

python3 tests/web/compare_writeups.py "$out/$name-desktop.html" "$out/$name-page.html"
