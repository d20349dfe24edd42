#!/usr/bin/env bash
# Installs what the clang checks need on top of scripts/setup.sh: Debian's clang (scripts/clang_build.sh),
# clang-tidy with run-clang-tidy (scripts/tidy_check.sh) and clang-format (scripts/format_check.sh). Only missing
# packages are installed, so running it twice is harmless; it needs root (or sudo) only when something is missing.
set -euo pipefail

packages=(clang clang-tidy clang-format)

"$(dirname "$0")/install_missing.sh" setup_clang "${packages[@]}"
