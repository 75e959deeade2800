"""A real client reads the tool's glb: Blender's own glTF importer, run headless, must give one
uv layer whose uv at every face corner is the tool's uv of that corner's vertex, as the OBJ of
the same input written by the tool says (its vt lines, one per vertex), and one face for each
triangle of the glb. Run by np_blender_test():

  blender -b --factory-startup --python-exit-code 1 --python blender_glb_uvs.py -- A.glb A.obj [B.glb B.obj ...]

The glb's vertices are matched to the OBJ's by position (float32 in the glb; Blender turns
glTF's y-up into its z-up): coincident vertices, welded by the tool, have the same uv.
"""

import json
import struct
import sys

import bpy

TOLERANCE = 1e-5  # the glb holds uvs as float32


def obj_uvs_by_position(path):
    positions, uvs = [], []
    for line in open(path):
        words = line.split()
        if words and words[0] == "v":
            positions.append(tuple(struct.unpack("3f", struct.pack("3f", *map(float, words[1:4])))))
        elif words and words[0] == "vt":
            uvs.append((float(words[1]), float(words[2])))
    assert len(positions) == len(uvs) > 0, f"{path}: {len(positions)} vertices, {len(uvs)} uvs"
    by_position = {}
    for p, uv in zip(positions, uvs):
        by_position.setdefault(p, []).append(uv)
    return by_position


def glb_triangles(path):
    data = open(path, "rb").read()
    length = struct.unpack_from("<I", data, 12)[0]
    gltf = json.loads(data[20:20 + length])
    return sum(gltf["accessors"][p["indices"]]["count"] // 3
               for mesh in gltf["meshes"] for p in mesh["primitives"] if p.get("mode", 4) == 4)


def check(glb, obj):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    # Smooth shading: the default, "NORMALS", fails in Debian 12 (Blender 3.4.1 asks NumPy 1.24 for
    # np.bool, which NumPy 1.24 does not have); the uvs are imported the same either way.
    bpy.ops.import_scene.gltf(filepath=glb, import_shading="SMOOTH")
    meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
    assert len(meshes) == 1, f"{glb}: {len(meshes)} mesh objects"
    mesh = meshes[0].data
    assert len(mesh.uv_layers) == 1, f"{glb}: {len(mesh.uv_layers)} uv layers"
    triangles = glb_triangles(glb)
    assert len(mesh.polygons) == triangles, f"{glb}: Blender has {len(mesh.polygons)} faces, the glb {triangles} triangles"
    expected = obj_uvs_by_position(obj)
    uv_layer = mesh.uv_layers[0].data
    worst = 0.0
    for loop in mesh.loops:
        x, y, z = mesh.vertices[loop.vertex_index].co
        position = tuple(struct.unpack("3f", struct.pack("3f", x, z, -y)))  # back to glTF's y-up
        assert position in expected, f"{glb}: Blender's vertex {loop.vertex_index} at {position} is no vertex of {obj}"
        u, v = uv_layer[loop.index].uv
        worst = max(worst, min(max(abs(u - a), abs(v - b)) for a, b in expected[position]))
    assert worst <= TOLERANCE, f"{glb}: a corner's uv is {worst} from the tool's"
    print(f"{glb}: {len(mesh.polygons)} faces, {len(mesh.loops)} corners, each with the tool's uv (within {worst:.2g})")


arguments = sys.argv[sys.argv.index("--") + 1:]
assert arguments and len(arguments) % 2 == 0, "usage: ... -- A.glb A.obj [B.glb B.obj ...]"
for k in range(0, len(arguments), 2):
    check(arguments[k], arguments[k + 1])
