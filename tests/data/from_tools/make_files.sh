#!/usr/bin/env bash
# Makes this folder's mesh files (and assets/suzanne.obj) with the real tools that write such files (Debian's blender and openscad; neither is
# needed to build or test MeshEdit: the files are committed). Run it again to make them anew:
#   apt-get install blender python3-numpy openscad && tests/data/from_tools/make_files.sh
set -euo pipefail
cd "$(dirname "$0")"
blender -b --factory-startup --python blender_exports.py -- "$PWD"
mv suzanne.obj ../../../assets/suzanne.obj  # the app ships it: the "bring your own mesh" lesson opens it
openscad -o bracket.stl bracket.scad
