#!/usr/bin/env bash
# Gradescope's image setup for a MeshEdit assignment (runs once, as root, when the autograder zip is uploaded):
# installs the build dependencies and builds the `meshedit` binary that run_autograder calls. The zip holds
# this file, run_autograder, and the MeshEdit source tree in a folder called meshedit/ (with the suites in
# meshedit/tests/grading/suites/ or wherever run_autograder's SUITE points).
set -euo pipefail
cd /autograder/source/meshedit
./scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DMESHEDIT_BUILD_TESTS=OFF
cmake --build build --target meshedit -j"$(nproc)"
