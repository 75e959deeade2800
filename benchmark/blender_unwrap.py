"""The add-on's own time in Blender: the operator against the module's call it makes, and against
Blender's own conformal unwrap, on a mesh subdivided in Blender. Run headless, once per module:

    blender -b --factory-startup --python benchmark/blender_unwrap.py -- \
        MODULE ADDON MESH.off STEPS ROUNDS SCRATCH [QUALITY...]

MODULE and ADDON: the directory of the module built by python/ and blender/norm_preserving_unwrap.py,
or the add-on's zip twice (then the zip's own module, built on the C and C++ runtime alone).
The mesh is read with the module, subdivided STEPS times at edge midpoints (bmesh's
subdivide_edges: each triangle into four, the vertex count of Loop subdivision) and, in every
round, mapped whole at each QUALITY (default: draft default) by the module's call on the arrays
the operator hands it, then by the
operator (in edit mode, which is entered and left outside the timing), then by Blender's
conformal unwrap. Prints one CSV row per measurement:
what,quality,round,vertices,seconds."""

import importlib
import pathlib
import shutil
import sys
import time

import bmesh
import bpy

module, addon, mesh_path, steps, rounds, scratch, *qualities = sys.argv[sys.argv.index("--") + 1:]
qualities = qualities or ["draft", "default"]
scratch = pathlib.Path(scratch)
shutil.rmtree(scratch, ignore_errors=True)
(scratch / "scripts" / "addons").mkdir(parents=True)
bpy.context.preferences.filepaths.script_directory = str(scratch / "scripts")
if addon.endswith(".zip"):
    bpy.ops.preferences.addon_install(filepath=addon, target="PREFS")
    bpy.ops.preferences.addon_enable(module="norm_preserving_unwrap")
    norm_preserving = importlib.import_module("norm_preserving_unwrap.norm_preserving")
else:
    sys.path.insert(0, module)
    import norm_preserving

    bpy.ops.preferences.addon_install(filepath=addon, target="PREFS")
    bpy.ops.preferences.addon_enable(module="norm_preserving_unwrap")

vertices, faces = norm_preserving.read_mesh(mesh_path)
bpy.ops.object.select_all(action="SELECT")
bpy.ops.object.delete()
data = bpy.data.meshes.new("mesh")
data.from_pydata(vertices.tolist(), [], faces.tolist())
bm = bmesh.new()
bm.from_mesh(data)
for _ in range(int(steps)):
    bmesh.ops.subdivide_edges(bm, edges=bm.edges[:], cuts=1, use_grid_fill=True)
bm.to_mesh(data)
bm.free()
obj = bpy.data.objects.new("mesh", data)
bpy.context.collection.objects.link(obj)
bpy.context.view_layer.objects.active = obj
obj.select_set(True)
count = len(data.vertices)
# The arrays the operator hands the module with every face selected (the vertices numbered in
# order of first use).
data.polygons.foreach_set("select", [True] * len(data.polygons))
faces = importlib.import_module("norm_preserving_unwrap").Faces(data)
assert len(faces.vertices) == count, (len(faces.vertices), count)


def timed(what, quality, round, call):
    start = time.perf_counter()
    call()
    print(f"{what},{quality},{round},{count},{time.perf_counter() - start:.3f}", flush=True)


print("what,quality,round,vertices,seconds")
for r in range(int(rounds)):
    for quality in qualities:
        timed("module", quality, r, lambda: norm_preserving.texture(faces.vertices, faces.polygons, quality=quality))
    # The operators in edit mode, every face selected (entering and leaving it is not timed).
    bpy.ops.object.mode_set(mode="EDIT")
    bpy.ops.mesh.select_all(action="SELECT")
    for quality in qualities:
        timed("operator", quality, r, lambda: bpy.ops.uv.norm_preserving_unwrap(quality=quality))
    timed("blender_conformal", "", r, lambda: bpy.ops.uv.unwrap(method="CONFORMAL", margin=0))
    bpy.ops.object.mode_set(mode="OBJECT")
