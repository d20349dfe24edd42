#!/usr/bin/env bash
# Holds the modules of engine/ to their one-way dependencies and their internal headers to their module. A file of
# engine/M may include "N/..." only when N is M or a module M needs (the meshedit_needs_M lists of the top-level
# CMakeLists.txt, the one table of who uses whom); "N/internal/..." may be included only from engine/N and tests/N.
# Prints each include that breaks a rule as FILE:LINE and fails. CTest runs it (module_check), so CI does.
set -euo pipefail
cd "$(dirname "$0")/.."

declare -A needs
while read -r module list; do
  needs[$module]="$list"
done < <(sed -n 's/^ *set(meshedit_needs_\([a-z]*\) \(.*\))$/\1 \2/p' CMakeLists.txt)

status=0
for folder in engine/*/; do
  module=$(basename "$folder")
  allowed=" $module ${needs[$module]:-} "
  while IFS=: read -r file line used; do
    if [[ "$allowed" != *" $used "* ]]; then
      echo "$file:$line: engine/$module includes $used/, which it does not use (CMakeLists.txt: meshedit_needs_$module)"
      status=1
    fi
  done < <(grep -rno '^#include "[a-z_]*/' "$folder" | sed 's/#include "\([a-z_]*\)\/$/\1/')
done
while IFS=: read -r file line owner; do
  if [[ "$file" != engine/"$owner"/* && "$file" != tests/"$owner"/* ]]; then
    echo "$file:$line: includes an internal header of engine/$owner (only engine/$owner and tests/$owner may)"
    status=1
  fi
done < <(grep -rno '^#include "[a-z_]*/internal/' engine tests | sed 's/#include "\([a-z_]*\)\/internal\/$/\1/')

if [ "$status" -eq 0 ]; then
  echo "module_check: every include in engine/ follows the modules' dependencies; internal headers stay in their module"
fi
exit "$status"
