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
  fonts-dejavu-core
  fonts-wqy-microhei
)

"$(dirname "$0")/install_missing.sh" setup "${packages[@]}"
