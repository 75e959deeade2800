"""Renders doc/figures/blender_unwrap.png: the cow of CGAL's collection after Blender's
Edit Mode > UV > Norm-preserving unwrap, with a checkerboard on the UV map. Run headless, under
Xvfb for Blender's OpenGL renderer (Workbench):

    xvfb-run -a blender -b --factory-startup --python doc/figures/render_blender_unwrap.py -- \
        build/python blender/norm_preserving_unwrap.py build/data/meshes/cow.off \
        doc/figures/blender_unwrap.png
"""

import importlib.util
import pathlib
import sys
import tempfile

import bpy
import mathutils
import numpy as np

module_dir, addon, cow_off, output = sys.argv[sys.argv.index("--") + 1:]
sys.path.insert(0, module_dir)
import norm_preserving  # noqa: E402

spec = importlib.util.spec_from_file_location("norm_preserving_unwrap", addon)
unwrap = importlib.util.module_from_spec(spec)
spec.loader.exec_module(unwrap)
unwrap.register()

# The cow through Blender's OBJ importer, as a user brings a mesh in: written by write_obj(), so
# that it comes with its material, the checkerboard (and a UV map of zeros, which the unwrap
# overwrites).
vertices, faces = norm_preserving.read_mesh(cow_off)
obj_base = pathlib.Path(tempfile.mkdtemp()) / "cow"
norm_preserving.write_obj(obj_base, vertices, faces, np.zeros((len(vertices), 2)))
bpy.ops.object.select_all(action="SELECT")
bpy.ops.object.delete()
bpy.ops.wm.obj_import(filepath=str(obj_base.with_suffix(".obj")))
cow = bpy.context.selected_objects[0]
bpy.context.view_layer.objects.active = cow
bpy.ops.object.shade_smooth()

bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.select_all(action="SELECT")
bpy.ops.uv.norm_preserving_unwrap(tiles=(2, 2))
bpy.ops.object.mode_set(mode="OBJECT")

# A camera three quarters from the front, looking at the cow's center.
corners = [cow.matrix_world @ mathutils.Vector(c) for c in cow.bound_box]
center = sum(corners, mathutils.Vector()) / 8
size = max((c - center).length for c in corners)
camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
bpy.context.collection.objects.link(camera)
camera.location = center + 2.6 * size * mathutils.Vector((0.75, -0.9, 0.45)).normalized()
camera.rotation_euler = (center - camera.location).to_track_quat("-Z", "Y").to_euler()
bpy.context.scene.camera = camera

scene = bpy.context.scene
scene.render.engine = "BLENDER_WORKBENCH"
scene.display.shading.light = "STUDIO"
scene.display.shading.color_type = "TEXTURE"
scene.render.resolution_x, scene.render.resolution_y = 640, 430
scene.render.film_transparent = False
scene.world.color = (1, 1, 1)
scene.render.image_settings.color_mode = "RGB"
scene.render.image_settings.compression = 100
scene.render.filepath = str(pathlib.Path(output).resolve())
bpy.ops.render.render(write_still=True)
