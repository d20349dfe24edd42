#!/usr/bin/env bash
# install_missing.sh NAME PACKAGE...: installs the Debian packages of the list that are not installed yet, and
# only those, so running it twice is harmless. Needs root (or sudo) only when something has to be installed.
# NAME prefixes its messages (setup.sh and setup_bench.sh share this script).
set -euo pipefail
name="$1"
shift
packages=("$@")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "$name: all ${#packages[@]} packages present"
  exit 0
fi

echo "$name: installing ${missing[*]}"
as_root=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "$name: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  as_root=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
