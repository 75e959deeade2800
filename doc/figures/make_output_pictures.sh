#!/usr/bin/env bash
# Makes the pictures of doc/manual.md's section on the command-line tool from the command-line tool's own outputs on the cow of
# CGAL's collection: its web page (--viewer) in headless Chromium with the checkerboard,
# doc/figures/viewer_cow.png, and with a photo as the texture, doc/figures/viewer_cow_photo.png,
# and its UV layout, doc/figures/texture_mesh_cow_uv.svg; and the three quality presets on CGAL's
# bear, doc/figures/quality_{draft,default,exact}.png. The photo is Blender's forest
# panorama (Debian's blender-data, CC0, by Greg Zaal), made into a JPEG by Blender.
# The intermediate files stay in the build directory.
#
# Usage: bash doc/figures/make_output_pictures.sh [build directory, default build]
# Needs chromium and blender (apt-get install chromium blender).

set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(mkdir -p "${1:-$root/build}" && cd "${1:-$root/build}" && pwd)
figures=$root/doc/figures
work=$build/output_pictures

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" --target texture_mesh -j"${JOBS:-2}"
rm -rf "$work" && mkdir -p "$work" && cd "$work"

# The photo: the panorama tone-mapped by Blender's Filmic view, saved as a JPEG.
cat >exr_to_jpeg.py <<'PYTHON'
import sys
import bpy
source, target = sys.argv[sys.argv.index("--") + 1:]
scene = bpy.context.scene
scene.view_settings.view_transform = "Filmic"
scene.view_settings.look = "Medium Contrast"
scene.render.image_settings.file_format = "JPEG"
scene.render.image_settings.quality = 88
bpy.data.images.load(source).save_render(target, scene=scene)
PYTHON
blender -b --factory-startup --python-exit-code 1 --python exr_to_jpeg.py -- \
  /usr/share/blender/datafiles/studiolights/world/forest.exr "$work/forest.jpg" >blender.log 2>&1

tool=$build/bin/texture_mesh
cow=$build/data/meshes/cow.off
"$tool" --quiet "$cow" cow --viewer
"$tool" --quiet "$cow" cow_photo.glb --texture forest.jpg --viewer

# Headless Chromium, kept off the network, with a profile of its own.
screenshot() {
  rm -rf profile && mkdir profile
  chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking \
    --disable-component-update --disable-sync --user-data-dir="$work/profile" --use-angle=swiftshader \
    --enable-unsafe-swiftshader --window-size=640,480 --virtual-time-budget=15000 --screenshot="$2" \
    "file://$work/$1" >>chromium.log 2>&1
}
for quality in draft default exact; do
  "$tool" --quiet "$build/data/meshes/bear.off" "bear_$quality" --quality "$quality" --viewer
done
screenshot cow.html "$figures/viewer_cow.png"
screenshot cow_photo.html "$figures/viewer_cow_photo.png"
for quality in draft default exact; do
  screenshot "bear_$quality.html" "$figures/quality_$quality.png"
done
cp cow_uv.svg "$figures/texture_mesh_cow_uv.svg"
ls -l "$figures"/viewer_cow.png "$figures"/viewer_cow_photo.png "$figures"/texture_mesh_cow_uv.svg "$figures"/quality_*.png
