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

"$(dirname "$0")/install_missing.sh" setup_bench "${packages[@]}"
echo "setup_bench: reconfigure (cmake -S . -B build) so CMake finds OpenMesh and CGAL"
