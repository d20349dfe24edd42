#!/usr/bin/env bash
# web_test.sh [ACTIONS [FILE [DRIVER OPTIONS...]]]: the web page's end-to-end check. Builds the site (scripts/web.sh
# --no-serve), serves it on a free localhost port, and opens FILE (default lessons/4_edge_flip.lua; "" for the start
# screen, the window with no file) in headless Chromium (SwiftShader WebGL) with the actions of ACTIONS (default
# tests/web/lesson4_flip.txt, the verbs of `meshedit FILE --actions`). tests/web/page_driver.py drives the page in
# real time over the DevTools protocol, with the DRIVER OPTIONS (--pick FILE, --drop FILE, --download NAME: a file for
# the page's picker, a file dropped on the page, a file the page must download; --ready, --click-panel, --keys,
# --viewport...: see page_driver.py), and reads the verdict from the page. Passes when the page reports "actions: all
# expectations held". MESHEDIT_PAGE_QUERY adds to the page's URL parameters ("check": ?check, Check my work at start).
# Keeps the page's last screenshot, its downloads and the server's log in build-web/test/. Exit
# status: 0 passed, 1 failed, 77 skipped (no emscripten, no chromium, or neither ../shared/vendor nor a network to
# fetch the pinned sources: CTest's skip code).
set -euo pipefail
cd "$(dirname "$0")/.."
actions="${1:-tests/web/lesson4_flip.txt}"
file="${2-lessons/4_edge_flip.lua}"
shift $(($# < 2 ? $# : 2))
name=$(basename "$actions" .txt)

for tool in emcmake chromium python3; do
  command -v "$tool" >/dev/null || { echo "web_test: skipped: no $tool (scripts/setup_web.sh installs it)"; exit 77; }
done
# The pinned ImGui, Lua and tinyxml2 sources come from ../shared/vendor, or else from upstream (scripts/web.sh).
if [ ! -d ../shared/vendor ] && ! python3 -c 'import urllib.request; urllib.request.urlopen("https://github.com", timeout=10)' \
  2>/dev/null; then
  echo "web_test: skipped: no ../shared/vendor and no way to download the pinned sources"
  exit 77
fi

./scripts/web.sh --no-serve >/dev/null
out=build-web/test
mkdir -p "$out"
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory build-web/site >"$out/server-$name.log" 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null' EXIT
for _ in $(seq 50); do
  python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/')" 2>/dev/null && break
  sleep 0.1
done

encoded=$(python3 -c 'import sys, urllib.parse; print(urllib.parse.quote(open(sys.argv[1]).read()))' "$actions")
query="file=$file${MESHEDIT_PAGE_QUERY:+&$MESHEDIT_PAGE_QUERY}"
if python3 tests/web/page_driver.py "http://127.0.0.1:$port/?$query&actions=$encoded" \
  --screenshot "$out/$name.png" --downloads "$out/downloads" "$@"; then
  echo "web_test: ${file:-the start screen} with $actions: all expectations held"
  exit 0
fi
echo "web_test: ${file:-the start screen} with $actions: FAILED (screenshot: $out/$name.png)"
exit 1
