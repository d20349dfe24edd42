#!/usr/bin/env bash
# web_check_match.sh MESHEDIT ACTIONS [STUDENT_FILE=FIXTURE...]: whether the web page's Check my work gives the verdict
# `meshedit grade --visible-only` gives for the same files and suite, word for word. The files: the packaged templates
# of scripts/student/, each STUDENT_FILE replaced by the file FIXTURE (flip.lua=tests/grading/students/flip_correct.lua).
# The desktop grades a folder of those files with the native binary MESHEDIT and the course's suite
# (tests/grading/suites/all.lua); the page (scripts/web_test.sh, the start screen) plays ACTIONS: with fixtures, the
# driver drops them on the page together once ACTIONS has written /tmp/ready.json, and ACTIONS starts the check; with
# none, the page opens with ?check. tests/web/compare_check_results.py then compares the desktop's results.json with
# the page's <script id="check-results">. Keeps NAME-desktop.json and NAME-page.json in build-web/test/. Exit status:
# 0 the same, 1 not (or a run failed), 77 skipped (web_test.sh's reasons: CTest's skip code).
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { echo "usage: web_check_match.sh MESHEDIT ACTIONS [STUDENT_FILE=FIXTURE...]"; exit 1; }
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

"$meshedit" grade --suite tests/grading/suites/all.lua --submission "$scratch/submission" --visible-only \
  --results "$out/$name-desktop.json" >"$scratch/desktop.log" 2>&1 || {
  cat "$scratch/desktop.log"
  echo "web_check_match: meshedit grade did not grade the files"
  exit 1
}

status=0
if [ ${#dropped[@]} -gt 0 ]; then
  ./scripts/web_test.sh "$actions" "" --ready /tmp/ready.json --drop "${dropped[@]}" \
    --check-results "$out/$name-page.json" --timeout 600 || status=$?
else
  MESHEDIT_PAGE_QUERY=check ./scripts/web_test.sh "$actions" "" --check-results "$out/$name-page.json" \
    --timeout 600 || status=$?
fi
[ "$status" -eq 0 ] || exit "$status"

python3 tests/web/compare_check_results.py "$out/$name-desktop.json" "$out/$name-page.json"
