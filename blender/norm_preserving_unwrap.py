"""Norm-preserving unwrap: Lai & Cheng's norm-preserving texture mapping in Blender's UV menu.

Edit Mode > UV (U) > Norm-preserving unwrap maps the selected faces of the mesh in edit mode (all
its visible faces when none is selected) into its active UV map, made if there is none, with one
uv per vertex and no seam: a closed mesh of any genus, with holes or in pieces, is mapped as it
is. One object at a time: with several objects in edit mode it reports an error and changes
nothing. It
calls the Python module norm_preserving, which must be installed for Blender's Python (on
Debian, `cmake --install` of the package puts it where Debian's blender finds it): doc/manual.md,
section 8 (Blender).
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

import bmesh
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
            import norm_preserving
        except ImportError as e:
            self.report({"ERROR"}, f"Norm-preserving unwrap needs the Python module norm_preserving ({e}): see doc/manual.md, section 8 (Blender)")
            return {"CANCELLED"}
        mesh = context.active_object.data
        bm = bmesh.from_edit_mesh(mesh)
        faces = [f for f in bm.faces if f.select] or [f for f in bm.faces if not f.hide]
        # The vertices of those faces, numbered in order of first use.
        index = {}
        polygons = [[index.setdefault(v, len(index)) for v in f.verts] for f in faces]
        vertices = np.array([v.co[:] for v in index], dtype=np.float64).reshape(-1, 3)
        try:
            uv, report = norm_preserving.texture(
                vertices, polygons if len({len(p) for p in polygons}) > 1 else np.array(polygons),
                **self.texture_options(bm, index))
        except (ValueError, TypeError, RuntimeError) as e:
            # Nothing is written: the mesh and its UV maps stay as they were.
            self.report({"ERROR"}, f"Norm-preserving unwrap: {e}")
            return {"CANCELLED"}
        layer = bm.loops.layers.uv.active or bm.loops.layers.uv.new("UVMap")
        for face, polygon in zip(faces, polygons):
            for loop, i in zip(face.loops, polygon):
                loop[layer].uv = uv[i]
        bmesh.update_edit_mesh(mesh)
        self.report({"INFO"}, f"Norm-preserving unwrap: {len(vertices)} vertices in {time.perf_counter() - start:.2f} s, "
                              f"objective {report.objective:.4g}, "
                              f"flipped area {100 * report.distortion.flipped_area_fraction:.1f}%")
        return {"FINISHED"}

    def texture_options(self, bm, index):
        """The keywords of norm_preserving.texture(); `index` numbers the mapped vertices."""
        options = dict(guess=self.guess, fit=self.fit, tiles=tuple(self.tiles), keep_coincident=self.keep_coincident,
                       refine_signs=self.refine_signs, refine_euclidean=self.refine_euclidean, quality=self.quality,
                       tolerance=self.tolerance or None, time_limit=self.time_limit or None)
        if self.use_fixed_pair:
            bm.verts.ensure_lookup_table()
            pair = [bm.verts[i] if i < len(bm.verts) else None for i in self.fixed_pair]
            if not all(v in index for v in pair):
                raise ValueError("a fixed vertex is not a vertex of the faces unwrapped")
            options["fixed_pair"] = tuple(index[v] for v in pair)
        return options


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
