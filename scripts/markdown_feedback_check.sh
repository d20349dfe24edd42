#!/usr/bin/env bash
# markdown_feedback_check.sh [MESHEDIT]
# markdown_feedback_check.sh --results RESULTS.json [OUT]
#
# Whether the Markdown feedback `meshedit grade` writes into Gradescope's results.json (test_output_format "md"),
# with the failure picture embedded in it as a data: URL, renders as intended in a real browser. Gradescope's own
# renderer is not available offline; CommonMark, which it follows, is: each failed test's `output` (and the
# submission's) goes through cmark, the CommonMark reference implementation, and the HTML is opened in headless
# Chromium, where a script in the page checks what a student would see and writes its findings into the DOM (read
# with --dump-dom):
# - every <img> has loaded (complete, naturalWidth > 0, no error event), is a data:image/png URL, is shown (not in a
#   closed <details>), has alt text, has the natural size of the PNG in pictures/test-N.png beside results.json, and
#   decoded to its last row; a test with that file has exactly one <img>, a test without it none;
# - the Markdown's headings are <h1>..<h6>, its code spans <code>, its fenced blocks <pre><code> (as many of each as
#   the Markdown source holds);
# - its <details> blocks are <details> elements, closed, with a visible <summary> first, whose folded text shows once
#   opened;
# - no Markdown or HTML syntax ("![", "```", "**", "](data:", "<details", "<summary", "</", a backslash escape such
#   as "\_") is in the visible text outside code blocks, with the <details> closed and opened.
# Before the browser, the embedded picture must be byte for byte the file in pictures/, and that file a whole PNG
# (every chunk's CRC, image data that inflates to every row).
# Each page is rendered twice. cmark's default (safe) omits raw HTML and dangerous URLs but keeps data:image/png URLs:
# the picture stays, the <details> tags go (their folded text then shows unfolded, and there must be no <details>).
# With --unsafe the raw HTML stays, as in a renderer that lets <details> through. Gradescope shows images in Markdown
# feedback; whether it keeps raw HTML such as <details> cannot be seen from here, so the feedback must read well both
# ways, and the picture must survive the strict one.
#
# Without --results: grades two submissions with MESHEDIT (default build/meshedit) and tests/grading/suites/all.lua:
# the solutions of tests/exercise/solutions/ (curve, patch, normals, split, upsample) with a failing flip.lua,
# tests/grading/students/flip_forgets_faces.lua (failed flip tests with pictures) and flip_breaks_face_cycle.lua
# (pictures and <details>); at least one failed test must have a picture. Then it checks that the test can fail: a
# copy of the first results.json with a picture's data URL cut short, and one with the picture left out of the
# Markdown, must both be refused. With --results: checks RESULTS.json (its pictures/ beside it) and nothing else.
#
# Keeps the HTML, the dumped DOM and a 1280x800 screenshot of each page in OUT (default: markdown-check/ beside
# MESHEDIT, build/markdown-check with --results). Exit status: 0 passed, 1 failed, 77 skipped (no chromium, cmark or
# python3, or MESHEDIT not built: CTest's skip code).
set -euo pipefail
cd "$(dirname "$0")/.."

results_only=""
if [ "${1:-}" = "--results" ]; then
  [ $# -ge 2 ] || { echo "usage: markdown_feedback_check.sh --results RESULTS.json [OUT]"; exit 1; }
  results_only=$(realpath "$2")
  out="${3:-build/markdown-check}"
else
  meshedit="${1:-build/meshedit}"
  [ -x "$meshedit" ] || { echo "markdown_feedback_check: skipped: $meshedit is not built"; exit 77; }
  meshedit=$(realpath "$meshedit")
  out="$(dirname "$meshedit")/markdown-check"
fi
for tool in chromium cmark python3; do
  command -v "$tool" >/dev/null || {
    echo "markdown_feedback_check: skipped: no $tool (scripts/setup_web.sh installs it)"
    exit 77
  }
done
mkdir -p "$out"
out=$(realpath "$out")
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# tests/web/markdown_feedback_page.py writes each page (the Markdown through cmark, with
# tests/web/markdown_feedback_check.js, the page's own check), reads the check's findings and spoils a copy of the
# feedback; see its header.

# Headless Chromium with the flags tests/web/page_driver.py starts it with (no GPU ones: no WebGL here), a fresh
# profile each time, a 1280x800 window. --dump-dom dumps the DOM once the page has loaded, after its load handler (the
# check) ran; the virtual time budget lets anything still pending settle first.
browse() {
  rm -rf "$scratch/profile"
  chromium --headless=new --no-sandbox --no-first-run --disable-background-networking --disable-component-update \
    --disable-sync --hide-scrollbars --window-size=1280,800 --user-data-dir="$scratch/profile" \
    --virtual-time-budget=10000 "$@" 2>>"$out/chromium.log"
}

# check RESULTS NAME: renders RESULTS's feedback both ways and checks each page; exit status 0 when both pass.
check() {
  local results=$1 name=$2 mode status=0 whole
  for mode in safe unsafe; do
    local page="$out/$name-$mode.html"
    rm -f "$page"
    echo "markdown_feedback_check: $name, cmark $mode:"
    whole=yes
    python3 tests/web/markdown_feedback_page.py html "$results" "$mode" "$page" || whole=""
    [ -f "$page" ] || return 1
    browse --dump-dom "file://$page" >"$out/$name-$mode.dom.html" || true
    browse --screenshot="$out/$name-$mode.png" "file://$page" >/dev/null || true
    if python3 tests/web/markdown_feedback_page.py verdict "$out/$name-$mode.dom.html" && [ -n "$whole" ]; then
      echo "markdown_feedback_check: $name, cmark $mode: renders as intended (screenshot $out/$name-$mode.png)"
    else
      echo "markdown_feedback_check: $name, cmark $mode: FAILED (page $page, screenshot $out/$name-$mode.png)"
      status=1
    fi
  done
  return "$status"
}

: >"$out/chromium.log"
if [ -n "$results_only" ]; then
  check "$results_only" "$(basename "$results_only" .json)"
  exit
fi

status=0
pictures=0
for student in flip_forgets_faces flip_breaks_face_cycle; do
  submission="$scratch/$student/submission"
  mkdir -p "$submission" "$out/$student"
  for part in curve patch normals split upsample; do cp "tests/exercise/solutions/$part.lua" "$submission/"; done
  cp "tests/grading/students/$student.lua" "$submission/flip.lua"
  rm -rf "$out/$student/pictures"
  "$meshedit" grade --suite tests/grading/suites/all.lua --submission "$submission" \
    --results "$out/$student/results.json" >"$out/$student/grade.log" 2>&1 || {
    cat "$out/$student/grade.log"
    echo "markdown_feedback_check: meshedit grade did not grade $student"
    exit 1
  }
  grep '^Score' "$out/$student/grade.log" | sed "s/^/markdown_feedback_check: $student: /"
  pictures=$((pictures + $(find "$out/$student/pictures" -name 'test-*.png' 2>/dev/null | wc -l)))
  check "$out/$student/results.json" "$student" || status=1
done
if [ "$pictures" -eq 0 ]; then
  echo "markdown_feedback_check: FAILED: no failed test has a picture to check (grade.log says why)"
  status=1
fi

# The check must refuse feedback whose picture is broken or missing.
for how in broken missing; do
  spoiled="$out/spoiled-$how/results.json"
  rm -rf "$out/spoiled-$how"
  if ! python3 tests/web/markdown_feedback_page.py spoil "$out/flip_forgets_faces/results.json" "$spoiled" "$how"; then
    echo "markdown_feedback_check: FAILED: no picture in flip_forgets_faces's feedback to leave $how"
    status=1
  elif check "$spoiled" "spoiled-$how" >"$out/spoiled-$how.log" 2>&1; then
    cat "$out/spoiled-$how.log"
    echo "markdown_feedback_check: FAILED: feedback with its picture $how passed the check"
    status=1
  else
    echo "markdown_feedback_check: feedback with its picture $how is refused, as it must be:"
    grep '^  [^0-9]' "$out/spoiled-$how.log" | grep -v '^  in Chromium' | sort -u | head -4
  fi
done

[ "$status" -eq 0 ] && echo "markdown_feedback_check: the feedback's Markdown and pictures render as intended"
exit "$status"
