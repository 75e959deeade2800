"""Norm-preserving unwrap: Lai & Cheng's norm-preserving texture mapping in Blender's UV menu.

Edit Mode > UV (U) > Norm-preserving unwrap maps the selected faces of the mesh in edit mode (all
its visible faces when none is selected) into its active UV map, made if there is none, with one
uv per vertex and no seam: a closed mesh of any genus, with holes or in pieces, is mapped as it
is. One object at a time: with several objects in edit mode it reports an error and changes
nothing. It
calls the Python module norm_preserving: the one beside it when it is installed from the zip
(norm_preserving_unwrap-VERSION-linux-x86_64.zip), else one installed for Blender's Python:
doc/manual.md, section 8 (Blender).
"""

bl_info = {
    "name": "Norm-preserving unwrap",
    "author": "The CGAL_norm_preserving_parameterization authors",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "3D Viewport > Edit Mode > UV > Norm-preserving unwrap",
    "description": "Unwraps a mesh of any topology with one uv per vertex and no seam (Lai & Cheng)",
    "category": "UV",
}

import time

import bpy
import numpy as np
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntVectorProperty


class UV_OT_norm_preserving_unwrap(bpy.types.Operator):
    """Unwrap the selected faces (all visible faces, if none is selected) with one uv per vertex and no seam"""

    bl_idname = "uv.norm_preserving_unwrap"
    bl_label = "Norm-preserving unwrap"
    bl_options = {"REGISTER", "UNDO"}

    # The options of norm_preserving.texture(), by its names (doc/manual.md, section 7 (Python)).
    guess: EnumProperty(
        name="Initial guess",
        description="The initial map, which sets the signs of the uv differences",
        items=[("xy", "XY-MinMax", "The paper's default: from the X and Y coordinates"),
               ("combination", "Combination", "Rotations and a sphere map, weighted: try it on CAD parts and high genus"),
               ("graph", "Graph-based", "Chains of the mesh's graph and B-splines")],
        default="xy")
    fit: EnumProperty(
        name="Fit",
        items=[("uniform", "Uniform", "Into [0,1]^2, keeping the aspect ratio"),
               ("clamp", "Clamp", "Each coordinate clamped to [0,1], as printed in the paper"),
               ("none", "None", "In the mesh's units")],
        default="uniform")
    tiles: IntVectorProperty(name="Tiles", description="The texture repeats M times along u and N along v",
                             size=2, default=(1, 1), min=1)
    use_fixed_pair: BoolProperty(name="Fixed pair", description="Hold the edge between two given vertices at its length",
                                 default=False)
    fixed_pair: IntVectorProperty(name="Vertices", description="The indices of the fixed edge's two vertices",
                                  size=2, default=(0, 1), min=0)
    keep_coincident: BoolProperty(name="Keep coincident vertices apart",
                                  description="Do not weld vertices at the same position (welded, they get one uv)",
                                  default=False)
    refine_signs: BoolProperty(name="Refine signs", description="Re-solve with the signs of the solution", default=False)
    refine_euclidean: BoolProperty(name="Refine Euclidean lengths",
                                   description="Then minimize the Euclidean edge-length error", default=False)
    quality: EnumProperty(
        name="Quality",
        items=[("draft", "Draft", "At most 2% above the optimum, fastest"),
               ("default", "Default", "Close to the optimum"),
               ("exact", "Exact", "The optimum, certified to 1e-9")],
        default="default")
    tolerance: FloatProperty(name="Tolerance", description="The solver's tolerance; 0: the quality's", default=0.0, min=0.0)
    time_limit: FloatProperty(name="Time limit", description="Seconds after which the solver stops with its best map; 0: none",
                              default=0.0, min=0.0, subtype="TIME_ABSOLUTE", unit="TIME_ABSOLUTE")

    @classmethod
    def poll(cls, context):
        return context.mode == "EDIT_MESH" and context.active_object is not None and context.active_object.type == "MESH"

    def execute(self, context):
        start = time.perf_counter()
        in_edit_mode = context.objects_in_mode
        if len(in_edit_mode) > 1:
            self.report({"ERROR"}, f"Norm-preserving unwrap maps one object at a time: {len(in_edit_mode)} objects are "
                                   "in edit mode (enter edit mode on one only)")
            return {"CANCELLED"}
        try:
            norm_preserving = load_module()
        except ImportError as e:
            self.report({"ERROR"}, f"Norm-preserving unwrap needs the Python module norm_preserving ({e}): "
                                   "see doc/manual.md, section 8 (Blender)")
            return {"CANCELLED"}
        mesh = context.active_object.data
        # The mesh's own arrays, read and written whole (foreach_get / foreach_set) in object
        # mode, where they hold the edits; back to edit mode whatever happens.
        bpy.ops.object.mode_set(mode="OBJECT")
        try:
            faces = Faces(mesh)
            try:
                uv, report = norm_preserving.texture(faces.vertices, faces.polygons, **self.texture_options(faces))
            except (ValueError, TypeError, RuntimeError) as e:
                # Nothing is written: the mesh and its UV maps stay as they were.
                self.report({"ERROR"}, f"Norm-preserving unwrap: {e}")
                return {"CANCELLED"}
            faces.write_uvs(uv)
        finally:
            bpy.ops.object.mode_set(mode="EDIT")
        self.report({"INFO"}, f"Norm-preserving unwrap: {len(faces.vertices)} vertices in "
                              f"{time.perf_counter() - start:.2f} s, objective {report.objective:.4g}, "
                              f"flipped area {100 * report.distortion.flipped_area_fraction:.1f}%")
        return {"FINISHED"}

    def texture_options(self, faces):
        """The keywords of norm_preserving.texture()."""
        options = dict(guess=self.guess, fit=self.fit, tiles=tuple(self.tiles), keep_coincident=self.keep_coincident,
                       refine_signs=self.refine_signs, refine_euclidean=self.refine_euclidean, quality=self.quality,
                       tolerance=self.tolerance or None, time_limit=self.time_limit or None)
        if self.use_fixed_pair:
            options["fixed_pair"] = faces.local_pair(self.fixed_pair)
        return options


def load_module():
    """The module beside the add-on (in the zip's add-on folder), else one installed for Blender's Python."""
    try:
        from . import norm_preserving
    except ImportError as beside:
        try:
            import norm_preserving
        except ImportError as installed:
            raise ImportError(f"not beside the add-on ({beside}), not installed ({installed})") from installed
    return norm_preserving


class Faces:
    """The selected faces of a mesh (all visible faces when none is selected), as a vertex array and
    polygons of indices into it, the vertices numbered in order of first use around the faces."""

    def __init__(self, mesh):
        self.mesh = mesh
        count = len(mesh.polygons)
        select, hide = np.empty(count, dtype=bool), np.empty(count, dtype=bool)
        mesh.polygons.foreach_get("select", select)
        mesh.polygons.foreach_get("hide", hide)
        chosen = np.flatnonzero(select if select.any() else ~hide)
        first, sides = np.empty(count, dtype=np.int64), np.empty(count, dtype=np.int64)
        mesh.polygons.foreach_get("loop_start", first)
        mesh.polygons.foreach_get("loop_total", sides)
        first, sides = first[chosen], sides[chosen]
        # The loops of the chosen faces, face after face.
        self.loops = np.repeat(first - np.cumsum(sides) + sides, sides) + np.arange(sides.sum())
        loop_vertex = np.empty(len(mesh.loops), dtype=np.int64)
        mesh.loops.foreach_get("vertex_index", loop_vertex)
        used, first_use, corner = np.unique(loop_vertex[self.loops], return_index=True, return_inverse=True)
        order = np.argsort(first_use)
        self.local = np.empty(len(mesh.vertices), dtype=np.int64)  # mesh vertex -> its index here, or -1
        self.local.fill(-1)
        self.local[used[order]] = np.arange(len(used))
        self.corners = self.local[used[corner]]
        positions = np.empty(3 * len(mesh.vertices))
        mesh.vertices.foreach_get("co", positions)
        self.vertices = positions.reshape(-1, 3)[used[order]]
        if not len(sides) or (sides == sides[0]).all():
            self.polygons = self.corners.reshape(-1, sides[0] if len(sides) else 3)
        else:
            self.polygons = [p.tolist() for p in np.split(self.corners, np.cumsum(sides)[:-1])]

    def local_pair(self, pair):
        """The mesh vertices `pair` as indices here."""
        local = [self.local[i] if 0 <= i < len(self.local) else -1 for i in pair]
        if min(local) < 0:
            raise ValueError("a fixed vertex is not a vertex of the faces unwrapped")
        return tuple(int(i) for i in local)

    def write_uvs(self, uv):
        """Writes the uv of each vertex to its loops in the faces, in the active UV map (made if none)."""
        layer = self.mesh.uv_layers.active or self.mesh.uv_layers.new(name="UVMap")
        uvs = np.empty(2 * len(self.mesh.loops))
        layer.data.foreach_get("uv", uvs)
        uvs = uvs.reshape(-1, 2)
        uvs[self.loops] = np.asarray(uv)[self.corners]
        layer.data.foreach_set("uv", uvs.ravel())


def menu_entry(self, context):
    self.layout.separator()
    self.layout.operator(UV_OT_norm_preserving_unwrap.bl_idname)


def register():
    bpy.utils.register_class(UV_OT_norm_preserving_unwrap)
    bpy.types.VIEW3D_MT_uv_map.append(menu_entry)


def unregister():
    bpy.types.VIEW3D_MT_uv_map.remove(menu_entry)
    bpy.utils.unregister_class(UV_OT_norm_preserving_unwrap)


if __name__ == "__main__":
    register()
