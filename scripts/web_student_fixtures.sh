# shellcheck shell=bash
# Sourced by the scripts that give the web page and the desktop the same student files (web_check_match.sh,
# web_writeup_match.sh): student_fixtures SCRATCH STUDENT_FILE=FIXTURE... fills SCRATCH/submission with the packaged
# templates of scripts/student/, each STUDENT_FILE replaced by the file FIXTURE, puts a copy of each FIXTURE under its
# student name in SCRATCH/drop, and lists those copies in the array `dropped` (what the page has dropped on it).
# Exits 1 naming a fixture that is missing.
student_fixtures() {
  local scratch=$1 pair student fixture
  shift
  mkdir -p "$scratch/submission" "$scratch/drop"
  cp scripts/student/*.lua "$scratch/submission/"
  dropped=()
  for pair in "$@"; do
    student=${pair%%=*}
    fixture=${pair#*=}
    [ -f "$fixture" ] || { echo "$(basename "$0"): no fixture $fixture"; exit 1; }
    cp "$fixture" "$scratch/submission/$student"
    cp "$fixture" "$scratch/drop/$student"
    dropped+=("$scratch/drop/$student")
  done
}
