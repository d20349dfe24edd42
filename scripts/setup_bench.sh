#!/usr/bin/env bash
# Installs what the peer benchmark (tests/bench/peer_bench.cpp) compares against: OpenMesh and CGAL
# (Debian 12 packages) with the headers and libraries CGAL needs. Only missing packages are installed,
# so running it twice is harmless; it needs root (or sudo) only when something has to be installed.
# Nothing else needs these packages: without them peer_bench builds and runs with MeshEdit alone.
set -euo pipefail

packages=(
  libopenmesh-dev
  libcgal-dev libeigen3-dev libgmp-dev libmpfr-dev libboost-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup_bench: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup_bench: installing ${missing[*]}"
as_root=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup_bench: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  as_root=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup_bench: done; reconfigure (cmake -S . -B build) so CMake finds OpenMesh and CGAL"
