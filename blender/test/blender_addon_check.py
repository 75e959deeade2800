"""The Blender add-on (blender/norm_preserving_unwrap.py) in a real Blender, headless:

    blender -b --factory-startup --python-exit-code 1 --python blender_addon_check.py -- \
        <directory of the module> <add-on> <cow.off> <scratch directory> <tools/texture_mesh/test/test_meshes.py>

or, for the zip an artist installs, with the zip as both the module and the add-on (and an empty
user configuration: BLENDER_USER_CONFIG and BLENDER_USER_SCRIPTS in the scratch directory), which
must then be the only norm_preserving module Blender's Python finds. It installs and enables the
add-on, imports the cow through Blender's OBJ importer (an OBJ written
by test_meshes.py's write_obj()), unwraps it in edit mode, and checks the UV map: one uv per
loop, the same for every loop of a vertex, finite, in [0,1]; that unselected faces keep their
uvs; that an error leaves the mesh and its UV maps as they were; and that with two objects in
edit mode the add-on reports an error and changes neither. Any failed check raises, which fails
the run (ctest blender_addon)."""

import contextlib
import importlib.util
import io
import pathlib
import re
import shutil
import sys

import bmesh
import bpy
import numpy as np

module_dir, addon, cow_off, scratch, test_meshes_path = sys.argv[sys.argv.index("--") + 1:]
scratch = pathlib.Path(scratch)
shutil.rmtree(scratch, ignore_errors=True)
scratch.mkdir(parents=True)

from_zip = addon.endswith(".zip")
if from_zip:
    # No module for Blender's Python: the zip's alone is tested.
    try:
        import norm_preserving
    except ImportError:
        pass
    else:
        raise AssertionError(f"Blender's Python finds a norm_preserving module ({norm_preserving.__file__}): "
                             "the zip's would not be the one tested")
else:
    # The module of the build tree, not an installed one.
    sys.path.insert(0, module_dir)
    import norm_preserving  # noqa: E402

    assert pathlib.Path(norm_preserving.__file__).parent.resolve() == pathlib.Path(module_dir).resolve()

# The OBJ writer of the command-line tool's tests.
spec = importlib.util.spec_from_file_location("test_meshes", test_meshes_path)
test_meshes = importlib.util.module_from_spec(spec)
spec.loader.exec_module(test_meshes)


def run_unwrap(**options):
    """Runs the operator; returns what it reported (Blender raises RuntimeError on an error report)."""
    said = io.StringIO()
    with contextlib.redirect_stdout(said):
        result = bpy.ops.uv.norm_preserving_unwrap(**options)
    print(said.getvalue(), end="")
    assert result == {"FINISHED"}, result
    return said.getvalue()


def unwrap_fails(**options):
    """Runs the operator, which must report an error; returns the error."""
    try:
        bpy.ops.uv.norm_preserving_unwrap(**options)
    except RuntimeError as e:
        return str(e)
    raise AssertionError("the operator did not fail")


def mesh_state(mesh):
    """The mesh's positions and every UV map's uvs, as arrays."""
    positions = np.empty(3 * len(mesh.vertices))
    mesh.vertices.foreach_get("co", positions)
    maps = {}
    for layer in mesh.uv_layers:
        uv = np.empty(2 * len(mesh.loops))
        layer.data.foreach_get("uv", uv)
        maps[layer.name] = uv
    return positions, maps


def same_state(a, b):
    return np.array_equal(a[0], b[0]) and a[1].keys() == b[1].keys() and all(np.array_equal(a[1][k], b[1][k]) for k in a[1])


def loop_uvs(mesh):
    uv = np.empty(2 * len(mesh.loops))
    mesh.uv_layers.active.data.foreach_get("uv", uv)
    vertex = np.empty(len(mesh.loops), dtype=np.int64)
    mesh.loops.foreach_get("vertex_index", vertex)
    return uv.reshape(-1, 2), vertex


def check_one_uv_per_vertex(uv, vertex, loops):
    """The `loops` have finite uvs in [0,1], equal across the loops of each vertex."""
    assert np.isfinite(uv[loops]).all() and uv[loops].min() >= 0 and uv[loops].max() <= 1
    order = np.argsort(vertex[loops], kind="stable")
    v, u = vertex[loops][order], uv[loops][order]
    first = np.searchsorted(v, v)  # the first loop of each loop's vertex
    assert np.array_equal(u, u[first]), "two loops of one vertex have different uvs"


def edit_mode(obj, select):
    """Edit mode on `obj` alone, with the faces selected where `select` is true (and no other)."""
    bpy.ops.object.mode_set(mode="OBJECT")
    bpy.ops.object.select_all(action="DESELECT")
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj
    bpy.ops.object.mode_set(mode="EDIT")
    assert list(bpy.context.objects_in_mode) == [obj]
    bm = bmesh.from_edit_mesh(obj.data)
    for element in [*bm.verts, *bm.edges, *bm.faces]:
        element.select = False
    for face, selected in zip(bm.faces, select):
        face.select_set(selected)
    bmesh.update_edit_mesh(obj.data)


# Install and enable the add-on as a user does (Edit > Preferences > Add-ons > Install): the zip
# into the (empty) user scripts directory, the file into a scripts directory of the scratch
# directory rather than the user's own.
if from_zip:
    bpy.ops.preferences.addon_install(filepath=addon)
else:
    bpy.context.preferences.filepaths.script_directory = str(scratch / "scripts")
    (scratch / "scripts" / "addons").mkdir(parents=True)
    bpy.ops.preferences.addon_install(filepath=addon, target="PREFS")
bpy.ops.preferences.addon_enable(module="norm_preserving_unwrap")
assert hasattr(bpy.types, "UV_OT_norm_preserving_unwrap")
if from_zip:
    # The add-on's own module, from its folder.
    norm_preserving = importlib.import_module("norm_preserving_unwrap.norm_preserving")
    installed = pathlib.Path(bpy.utils.user_resource("SCRIPTS", path="addons")) / "norm_preserving_unwrap"
    assert pathlib.Path(norm_preserving.__file__).parent.resolve() == installed.resolve(), norm_preserving.__file__
assert any(f.__name__ == "menu_entry" for f in bpy.types.VIEW3D_MT_uv_map._dyn_ui_initialize())

# The cow, as an OBJ file (CGAL's is OFF), through Blender's OBJ importer.
vertices, faces = norm_preserving.read_mesh(cow_off)
cow_obj = scratch / "cow.obj"
test_meshes.write_obj(vertices.tolist(), faces.tolist(), cow_obj)
bpy.ops.object.select_all(action="SELECT")
bpy.ops.object.delete()
bpy.ops.wm.obj_import(filepath=str(cow_obj))
cow = bpy.context.selected_objects[0]
mesh = cow.data
assert len(mesh.vertices) == len(vertices) and len(mesh.polygons) == len(faces) and len(mesh.uv_layers) == 0

# The whole cow: a UV map is made, and every vertex has one uv.
edit_mode(cow, [True] * len(mesh.polygons))
said = run_unwrap()
assert re.search(r"Norm-preserving unwrap: 2904 vertices in [0-9.]+ s, objective [0-9.e+-]+, flipped area [0-9.]+%", said), said
bpy.ops.object.mode_set(mode="OBJECT")
assert [layer.name for layer in mesh.uv_layers] == ["UVMap"]
uv, vertex = loop_uvs(mesh)
assert len(uv) == len(mesh.loops)
check_one_uv_per_vertex(uv, vertex, np.arange(len(mesh.loops)))

# Half the faces selected: their loops get one uv per vertex, the others keep theirs.
mesh.uv_layers.active.data.foreach_set("uv", np.full(2 * len(mesh.loops), 7.0))
selected = np.arange(len(mesh.polygons)) < len(mesh.polygons) // 2
edit_mode(cow, selected.tolist())
run_unwrap(guess="combination", tiles=(1, 1), refine_signs=True)
bpy.ops.object.mode_set(mode="OBJECT")
uv, vertex = loop_uvs(mesh)
loop_face = np.repeat(np.arange(len(mesh.polygons)), 3)
check_one_uv_per_vertex(uv, vertex, np.flatnonzero(selected[loop_face]))
assert (uv[~selected[loop_face]] == 7.0).all()

# An error (a fixed pair that is not an edge) is reported, and nothing changes.
before = mesh_state(mesh)
edit_mode(cow, [True] * len(mesh.polygons))
error = unwrap_fails(use_fixed_pair=True, fixed_pair=(0, 1000))
assert "the fixed vertices are not the two ends of an edge" in error, error
bpy.ops.object.mode_set(mode="OBJECT")
assert same_state(before, mesh_state(mesh))

# A mesh of zero extent with no UV map: the error, and no UV map made.
flat = bpy.data.meshes.new("point")
flat.from_pydata([(1.0, 2.0, 3.0)] * 4, [], [(0, 1, 2), (0, 2, 3)])
point = bpy.data.objects.new("point", flat)
bpy.context.collection.objects.link(point)
before = mesh_state(flat)
edit_mode(point, [True, True])
error = unwrap_fails()
assert "zero extent" in error, error
bpy.ops.object.mode_set(mode="OBJECT")
assert len(flat.uv_layers) == 0 and same_state(before, mesh_state(flat))

# Two objects in edit mode at once: the error, and neither changes.
before = mesh_state(mesh), mesh_state(flat)
bpy.ops.object.mode_set(mode="OBJECT")
bpy.ops.object.select_all(action="DESELECT")
cow.select_set(True)
point.select_set(True)
bpy.context.view_layer.objects.active = cow
bpy.ops.object.mode_set(mode="EDIT")
assert len(bpy.context.objects_in_mode) == 2, bpy.context.objects_in_mode
error = unwrap_fails()
assert "maps one object at a time: 2 objects are in edit mode" in error, error
bpy.ops.object.mode_set(mode="OBJECT")
assert same_state(before[0], mesh_state(mesh)) and same_state(before[1], mesh_state(flat)) and len(flat.uv_layers) == 0
print("blender_addon: all checks passed")
