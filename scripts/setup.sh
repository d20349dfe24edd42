#!/usr/bin/env bash
# Installs every Debian package MeshEdit builds, tests or runs with, and only those that are missing,
# so running it twice is harmless. Needs root (or sudo) only when something has to be installed.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libglm-dev libtinyxml2-dev nlohmann-json3-dev libtinygltf-dev libstb-dev
  liblua5.4-dev lua5.4
  libglfw3-dev libimgui-dev libepoxy-dev libgl-dev libegl-dev libegl1-mesa-dev libgl1-mesa-dri mesa-utils
  googletest libgtest-dev
  xvfb xauth x11-utils
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
as_root=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  as_root=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
