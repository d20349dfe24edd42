#!/usr/bin/env bash
# Runs luacheck (Debian's lua-check) over every Lua file of the repository (lessons, exercises, student templates,
# the LuaLS api files, grading suites, solutions and every fixture) with the settings of .luacheckrc: Lua 5.4, the
# globals each kind of file really has, unused and shadowed names, 120 columns. Fails naming file:line:column of
# every warning. Installs lua-check if it is missing (scripts/install_missing.sh). CI runs it (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install_missing.sh lua_check lua-check >/dev/null
mapfile -d '' files < <(git ls-files -z -- '*.lua')
status=0
report=$(luacheck --formatter plain --codes --no-color -- "${files[@]}" 2>&1) || status=$?
if [ "$status" -ne 0 ]; then
  echo "$report"
  echo "lua_check: luacheck found something in $(echo "$report" | cut -d: -f1 | sort -u | wc -l) files (above;" \
    "the settings are in .luacheckrc)" >&2
  exit 1
fi
echo "lua_check: no warning in ${#files[@]} Lua files (.luacheckrc excludes the two that do not compile on purpose)"
