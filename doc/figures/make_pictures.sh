#!/usr/bin/env bash
# Makes the pictures of doc/pictures.md: for the cow, the camel, bunny00 and eight (genus 2)
# of CGAL's collection, textured by ours, LSCM and ARAP, a POV-Ray rendering
# doc/figures/<mesh>_<method>.png and the uv layout doc/figures/<mesh>_<method>_uv.svg.
# The POV-Ray scenes stay in the build directory.
#
# Usage: bash doc/figures/make_pictures.sh [build directory, default build]
# JOBS (default 2) sets the build's parallelism. Needs povray, installed if missing (root).

set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(mkdir -p "${1:-$root/build}" && cd "${1:-$root/build}" && pwd)
figures=$root/doc/figures
scenes=$build/pictures

if ! command -v povray >/dev/null; then
  apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y povray
fi
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" --target render_pictures -j"${JOBS:-2}"
mkdir -p "$scenes"

# mesh, its view (up axis, azimuth and elevation in degrees around it) and checker cells
# across [0,1] (eight has 634 triangles: 16 cells would be smaller than its triangles)
views=(
  "cow --up y --view 35 20 --cells 16"
  "camel --up y --view 35 20 --cells 16"
  "bunny00 --up y --view 80 15 --cells 16"
  "eight --up y --view 30 55 --cells 8"
)
for entry in "${views[@]}"; do
  read -r mesh view <<<"$entry"
  for method in ours lscm arap; do
    name=${mesh}_$method
    # shellcheck disable=SC2086 # $view is a list of options
    "$build/tools/render_pictures/render_pictures" "$build/data/meshes/$mesh.off" "$method" \
      "$scenes/$name.pov" "$figures/${name}_uv.svg" $view
    if ! povray +I"$scenes/$name.pov" +O"$figures/$name.png" +W640 +H480 +A0.3 -D >"$scenes/$name.log" 2>&1; then
      cat "$scenes/$name.log" >&2
      exit 1
    fi
  done
done
ls -l "$figures"/*.png "$figures"/*_uv.svg
