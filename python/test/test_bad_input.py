"""Bad input raises TypeError or ValueError with the package's message, before any work, and the
caller's arrays are never modified (they are passed read-only, and compared after the call)."""

import numpy as np
import pytest

import norm_preserving
from conftest import quad_grid

VERTICES, FACES = quad_grid(2, 2)  # 9 vertices, 4 quads


def read_only(array):
    array = np.array(array)
    array.flags.writeable = False
    return array


def with_nan(vertices, row):
    vertices = np.array(vertices)
    vertices[row, 1] = np.nan
    return vertices


# (vertices, faces, options, exception, the message's expected words)
BAD_INPUT = {
    "vertices of 2 coordinates": (VERTICES[:, :2], FACES, {}, ValueError, r"vertices must be an \(n, 3\) array, not of shape \(9, 2\)"),
    "vertices of 3 dimensions": (VERTICES[None], FACES, {}, ValueError, r"vertices must be an \(n, 3\) array"),
    "vertices as strings": (VERTICES.astype(str), FACES, {}, TypeError, "vertices must hold numbers, not str"),
    "complex vertices": (VERTICES.astype(complex), FACES, {}, TypeError, "vertices must hold numbers, not complex128"),
    "no vertices at all": (None, FACES, {}, TypeError, "vertices must hold numbers, not object"),
    "float faces": (VERTICES, FACES.astype(float), {}, TypeError, "faces must hold integer vertex indices, not float64"),
    "boolean faces": (VERTICES, FACES > 2, {}, TypeError, "faces must hold integer vertex indices, not bool"),
    "faces as a string": (VERTICES, "0 1 2", {}, TypeError, "faces must hold integer vertex indices"),
    "a face list holding floats": (VERTICES, [[0, 1, 4], [0.5, 1, 2, 3]], {}, TypeError, "faces must hold integer vertex indices, not float64"),
    "a flat index array": (VERTICES, FACES.ravel(), {}, ValueError, r"faces must be an \(m, k\) array or a sequence of index sequences"),
    "an index out of range": (VERTICES, [[0, 1, 4], [1, 2, 99]], {}, ValueError, "face 1 refers to vertex 99 of 9"),
    "a negative index": (VERTICES, np.array([[0, 1, 4], [-1, 2, 5]], dtype=np.int8), {}, ValueError, "face 1 refers to vertex -1 of 9"),
    "an unsigned index beyond int64": (VERTICES, np.array([[0, 1, 2**64 - 1]], dtype=np.uint64), {}, ValueError, "face 0 refers to vertex"),
    "no face": (VERTICES, np.zeros((0, 3), dtype=int), {}, ValueError, "the mesh has no face"),
    "an empty face list": (VERTICES, [], {}, ValueError, "the mesh has no face"),
    "an empty mesh": (np.zeros((0, 3)), np.zeros((0, 3), dtype=int), {}, ValueError, "the mesh has no face"),
    "NaN on a face": (with_nan(VERTICES, 4), FACES, {}, ValueError, "vertex 4 has a non-finite coordinate"),
    "zero extent": (np.ones((9, 3)), FACES, {}, ValueError, "zero extent"),
    "an unknown guess": (VERTICES, FACES, {"guess": "XY"}, ValueError, "guess takes xy, combination or graph"),
    "an unknown fit": (VERTICES, FACES, {"fit": "stretch"}, ValueError, "fit takes uniform, clamp or none"),
    "no tile": (VERTICES, FACES, {"tiles": (0, 1)}, ValueError, "tiles takes M and N of at least 1"),
    "an unknown quality": (VERTICES, FACES, {"quality": "best"}, ValueError, "quality takes draft, default or exact"),
    "a negative tolerance": (VERTICES, FACES, {"tolerance": -1.0}, ValueError, "tolerance takes a positive number"),
    "a NaN tolerance": (VERTICES, FACES, {"tolerance": float("nan")}, ValueError, "tolerance takes a positive number"),
    "no time": (VERTICES, FACES, {"time_limit": 0.0}, ValueError, "time limit takes a positive number of seconds"),
    "a negative fixed vertex": (VERTICES, FACES, {"fixed_pair": (-1, 0)}, ValueError, "fixed_pair takes two vertex indices"),
    "a fixed vertex out of range": (VERTICES, FACES, {"fixed_pair": (0, 9)}, ValueError, "a fixed vertex is not a vertex of the mesh"),
    "a fixed pair that is no edge": (VERTICES, FACES, {"fixed_pair": (0, 8)}, ValueError, "the fixed vertices are not the two ends of an edge"),
    "a guess that is no string": (VERTICES, FACES, {"guess": 3}, TypeError, "incompatible function arguments"),
    "an unknown option": (VERTICES, FACES, {"weld": False}, TypeError, "incompatible function arguments"),
    "a progress that is no callable": (VERTICES, FACES, {"progress": 5}, TypeError, "incompatible function arguments"),
}


@pytest.mark.parametrize("vertices, faces, options, error, message", BAD_INPUT.values(), ids=BAD_INPUT.keys())
def test_bad_input_raises_with_the_message_and_leaves_the_arrays_alone(vertices, faces, options, error, message):
    if isinstance(vertices, np.ndarray):
        vertices = read_only(vertices)
    if isinstance(faces, np.ndarray):
        faces = read_only(faces)
    before = (np.copy(vertices), np.copy(faces) if isinstance(faces, np.ndarray) else faces)
    with pytest.raises(error, match=message):
        norm_preserving.texture(vertices, faces, **options)
    if isinstance(vertices, np.ndarray):
        assert np.array_equal(vertices, before[0], equal_nan=vertices.dtype.kind in "fc")
    if isinstance(faces, np.ndarray):
        assert np.array_equal(faces, before[1])


def test_every_call_leaves_read_only_arrays_as_they_were(cow, tmp_path):
    vertices, faces = read_only(cow[0]), read_only(cow[1])
    copies = vertices.copy(), faces.copy()
    uv, _ = norm_preserving.texture(vertices, faces)
    uv = read_only(uv)
    norm_preserving.measure_distortion(vertices, faces, uv)
    norm_preserving.lscm(vertices, faces)
    norm_preserving.write_obj(str(tmp_path / "cow"), vertices, faces, uv)
    assert np.array_equal(vertices, copies[0]) and np.array_equal(faces, copies[1])


def test_measure_distortion_refuses_a_uv_per_corner(cow):
    vertices, faces = cow
    with pytest.raises(ValueError, match="uv must have one row per vertex: 5804 rows for 2904 vertices"):
        norm_preserving.measure_distortion(vertices, faces, np.zeros((len(faces), 2)))


def test_lscm_refuses_a_non_manifold_soup():
    # Three triangles on one edge.
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], dtype=float)
    with pytest.raises(ValueError, match="do not form an oriented 2-manifold"):
        norm_preserving.lscm(vertices, [[0, 1, 2], [1, 0, 3], [0, 1, 4]])


def test_read_mesh_says_why_it_cannot_read(tmp_path):
    with pytest.raises(FileNotFoundError, match="no such file"):
        norm_preserving.read_mesh(tmp_path / "missing.off")
    garbage = tmp_path / "garbage.off"
    garbage.write_text("this is no mesh\n")
    with pytest.raises(ValueError, match="cannot read .*garbage.off: not a valid off file"):
        norm_preserving.read_mesh(garbage)
