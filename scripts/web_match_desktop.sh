#!/usr/bin/env bash
# web_match_desktop.sh MESHEDIT ACTIONS FILE [COMPARE OPTIONS...]: whether the web page shows what the desktop window
# shows. Plays ACTIONS on FILE ("" for the start screen) in the desktop window of the native binary MESHEDIT at
# 1280x800 (under DISPLAY, whose screen must be at least that large, or else an Xvfb of its own) and in the page
# (scripts/web_test.sh, a 1280x800 viewport); ACTIONS ends with `screenshot desktop_match.png`, which the desktop writes
# in a scratch folder and the page downloads. tests/web/compare_screenshots.py compares the two PNGs with the COMPARE
# OPTIONS (--ignore X,Y,W,H for what is meant to differ). Keeps NAME-desktop.png, NAME-page.png and NAME-diff.png
# (the differences in red) in build-web/test/. Exit status: 0 they match, 1 not (or a run failed), 77 skipped (no
# X server and no Xvfb, or web_test.sh's reasons: CTest's skip code).
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 3 ] || { echo "usage: web_match_desktop.sh MESHEDIT ACTIONS FILE [COMPARE OPTIONS...]"; exit 1; }
meshedit=$(realpath "$1")
actions=$2
file=$3
shift 3
name=$(basename "$actions" .txt)
out=build-web/test
mkdir -p "$out"
scratch=$(mktemp -d)
xvfb=""
cleanup() {
  [ -n "$xvfb" ] && kill "$xvfb" 2>/dev/null
  rm -rf "$scratch"
}
trap cleanup EXIT

if [ -z "${DISPLAY:-}" ]; then
  command -v Xvfb >/dev/null || { echo "web_match_desktop: skipped: no DISPLAY and no Xvfb"; exit 77; }
  # -displayfd: Xvfb takes a free display number and writes it when it is ready.
  Xvfb -displayfd 5 -screen 0 1280x800x24 5>"$scratch/display" >"$scratch/xvfb.log" 2>&1 &
  xvfb=$!
  for _ in $(seq 100); do
    [ -s "$scratch/display" ] && break
    sleep 0.1
  done
  [ -s "$scratch/display" ] || { echo "web_match_desktop: Xvfb did not start"; exit 1; }
  export DISPLAY=":$(tr -d '[:space:]' <"$scratch/display")"
fi

# The desktop: fresh settings, a 1280x800 window, the screenshot written in the scratch folder.
target=""
[ -n "$file" ] && target=$(realpath "$file")
script=$(realpath "$actions")
(cd "$scratch" && XDG_CONFIG_HOME="$scratch/config" timeout 300 "$meshedit" ${target:+"$target"} --size 1280x800 \
  --actions "$script" >"$scratch/desktop.log" 2>&1) || {
  cat "$scratch/desktop.log"
  echo "web_match_desktop: the desktop window did not play $actions"
  exit 1
}
cp "$scratch/desktop_match.png" "$out/$name-desktop.png"

# The page: the same actions at a 1280x800 viewport; its screenshot arrives as a download.
status=0
./scripts/web_test.sh "$actions" "$file" --viewport 1280x800 --download desktop_match.png || status=$?
[ "$status" -eq 0 ] || exit "$status"
cp "$out/downloads/desktop_match.png" "$out/$name-page.png"

python3 tests/web/compare_screenshots.py "$out/$name-desktop.png" "$out/$name-page.png" --diff "$out/$name-diff.png" \
  "$@"
