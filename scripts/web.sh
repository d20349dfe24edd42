#!/usr/bin/env bash
# web.sh [--no-serve | --measure] [PORT]: builds the web page (emscripten, the "web" preset: build-web/site) and serves
# it on http://localhost:PORT/ (default 8080) with python3's static file server until interrupted. Prints the size of
# the .wasm, .data and .js files. --measure serves nothing: it opens lesson 4 in headless Chromium (scripts/web_test.sh)
# and prints the time from the page's start to its first frame and the median time between the frames after it.
# Needs scripts/setup_web.sh's packages; the pinned ImGui, Lua and tinyxml2 archives come from ../shared/vendor when it
# exists, else from upstream (MESHEDIT_VENDOR_DIR, cmake/web.cmake).
set -euo pipefail
cd "$(dirname "$0")/.."

serve=1
measure=0
case "${1:-}" in
  --no-serve) serve=0; shift ;;
  --measure) serve=0; measure=1; shift ;;
esac
port="${1:-8080}"

command -v emcmake >/dev/null || { echo "web.sh: no emscripten (run scripts/setup_web.sh)" >&2; exit 1; }
# emscripten's JavaScript tools need Debian's node modules even when another node comes first on PATH.
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"

vendor=()
if [ ! -d ../shared/vendor ]; then
  vendor=(-DMESHEDIT_VENDOR_DIR=)  # no vendor folder here: download the pinned tags
fi
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake --preset web "${vendor[@]}" "${launcher[@]}" >/dev/null
cmake --build build-web -j"${JOBS:-2}" --target meshedit

site=build-web/site
for f in meshedit.wasm meshedit.data meshedit.js; do
  bytes=$(stat -c %s "$site/$f")
  echo "web.sh: $f: $bytes bytes ($((bytes / 1024)) KiB)"
done
echo "web.sh: the site is $site (index.html, meshedit.js, meshedit.wasm, meshedit.data): copy it to any static host"

if [ "$measure" = 1 ]; then
  actions=$(mktemp)
  trap 'rm -f "$actions"' EXIT
  printf 'frames 40\nquit\n' >"$actions"
  ./scripts/web_test.sh "$actions" lessons/4_edge_flip.lua | grep -E '^page_driver: (first frame|frames )' |
    sed 's/^page_driver/web.sh/'
fi

if [ "$serve" = 1 ]; then
  echo "web.sh: serving on http://localhost:$port/ (Ctrl-C stops)"
  exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$site"
fi
