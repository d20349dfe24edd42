#!/usr/bin/env bash
# Installs what the web build (docs/WEB.md) needs on top of scripts/setup.sh's packages, and only what is missing,
# so running it twice is harmless: Debian's emscripten (the compiler, its GLFW/WebGL ports and its Node.js tools),
# Chromium to open the page headless, cmark (CommonMark's reference renderer: scripts/markdown_feedback_check.sh
# renders the grader's Markdown feedback with it for Chromium), python3 to serve the site locally, and fonttools
# (pyftsubset: the page's Chinese font, scripts/font_subset.py). The pinned
# upstream sources the build compiles (ImGui, Lua, tinyxml2) are not packages: the build takes them from
# MESHEDIT_VENDOR_DIR or downloads them.
set -euo pipefail
here="$(dirname "$0")"

"$here/setup.sh"

packages=(
  emscripten
  chromium
  cmark
  python3
  fonttools
)

"$here/install_missing.sh" setup_web "${packages[@]}"
