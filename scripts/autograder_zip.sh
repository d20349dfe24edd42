#!/usr/bin/env bash
# autograder_zip.sh [ZIP]: makes the autograder zip that Gradescope's "Configure Autograder" takes (default
# build/autograder.zip): setup.sh and run_autograder from tests/grading/gradescope/ at its top, and the MeshEdit
# source tree in meshedit/ as this checkout has it (every file git tracks or would track, with uncommitted edits,
# without build folders or anything .gitignore leaves out), so an instructor's own suites go in with it.
# tests/grading/gradescope/README.md says how to upload it and how to try it (scripts/autograder_trial.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
zip_path="$(realpath -m "${1:-build/autograder.zip}")"
command -v zip >/dev/null || { echo "autograder_zip: needs zip (apt-get install zip)" >&2; exit 1; }
git rev-parse --is-inside-work-tree >/dev/null 2>&1 ||
  { echo "autograder_zip: $(pwd) is not a git checkout; the zip takes the files git tracks" >&2; exit 1; }

stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/meshedit"
git ls-files -z --cached --others --exclude-standard | while IFS= read -r -d '' f; do
  [ -e "$f" ] || continue # tracked but deleted in this checkout
  mkdir -p "$stage/meshedit/$(dirname "$f")"
  cp -p "$f" "$stage/meshedit/$f"
done
cp -p tests/grading/gradescope/setup.sh tests/grading/gradescope/run_autograder "$stage/"

mkdir -p "$(dirname "$zip_path")"
rm -f "$zip_path"
(cd "$stage" && zip -qr -X "$zip_path" setup.sh run_autograder meshedit)
echo "autograder_zip: $zip_path ($(du -h "$zip_path" | cut -f1), $(find "$stage/meshedit" -type f | wc -l) files in meshedit/)"
