#!/usr/bin/env bash
# web_test.sh [ACTIONS [FILE]]: the web page's end-to-end check. Builds the site (scripts/web.sh --no-serve), serves it
# on a free localhost port, opens FILE (default lessons/4_edge_flip.lua; "" for the start screen, the window with no
# file) in headless Chromium (SwiftShader WebGL) with the actions of ACTIONS (default tests/web/lesson4_flip.txt, the
# verbs of `meshedit FILE --actions`), and passes when the page reports "actions: all expectations held". It also
# keeps a screenshot of FILE at 1280x800 in build-web/test/. Exit status: 0 passed, 1 failed, 77 skipped (no
# emscripten or no chromium: CTest's skip code).
set -euo pipefail
cd "$(dirname "$0")/.."
actions="${1:-tests/web/lesson4_flip.txt}"
file="${2-lessons/4_edge_flip.lua}"
shot=$(basename "${file:-start}" .lua).png

for tool in emcmake chromium python3; do
  command -v "$tool" >/dev/null || { echo "web_test: skipped: no $tool (scripts/setup_web.sh installs it)"; exit 77; }
done

./scripts/web.sh --no-serve >/dev/null
out=build-web/test
mkdir -p "$out"
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory build-web/site >"$out/server.log" 2>&1 &
server=$!
profile=$(mktemp -d)
trap 'kill "$server" 2>/dev/null; rm -rf "$profile"' EXIT
for _ in $(seq 50); do
  python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/')" 2>/dev/null && break
  sleep 0.1
done

# Chromium as root needs --no-sandbox; the background-networking flags keep it off the network.
browser=(chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader --no-first-run
  --disable-background-networking --disable-component-update --disable-sync --window-size=1280,800
  --virtual-time-budget=30000)
encoded=$(python3 -c 'import sys, urllib.parse; print(urllib.parse.quote(open(sys.argv[1]).read()))' "$actions")
"${browser[@]}" --user-data-dir="$profile/a" --dump-dom \
  "http://127.0.0.1:$port/?file=$file&actions=$encoded" >"$out/page.html" 2>"$out/chromium.log" || true
"${browser[@]}" --user-data-dir="$profile/b" --screenshot="$out/$shot" \
  "http://127.0.0.1:$port/?file=$file" >/dev/null 2>&1 || true

# What the program printed (<pre id="log">), then the verdict from <body data-actions>.
sed -n '/<pre id="log">/,/<\/pre>/p' "$out/page.html" | sed 's/<[^>]*>//g'
if grep -q 'data-actions="actions: all expectations held"' "$out/page.html"; then
  echo "web_test: ${file:-the start screen} with $actions: all expectations held (page: $out/page.html)"
  exit 0
fi
echo "web_test: ${file:-the start screen} with $actions: FAILED (page: $out/page.html, browser log: $out/chromium.log)"
exit 1
