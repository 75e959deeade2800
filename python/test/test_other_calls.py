"""lscm(), arap(), measure_distortion(), read_mesh(), write_obj() and the README's example."""

import os
import pathlib
import re
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import norm_preserving
from conftest import mesh_path, quad_grid


def uvs_per_vertex(faces, corner_uv):
    """The distinct uvs of each vertex over its corners."""
    seen = {}
    for face, uvs in zip(faces, corner_uv):
        for vertex, uv in zip(face, uvs):
            seen.setdefault(int(vertex), set()).add(tuple(uv))
    return seen


@pytest.mark.parametrize("method", [norm_preserving.lscm, norm_preserving.arap])
def test_cut_methods_give_a_uv_per_corner_split_only_along_the_cut(cow, method):
    vertices, faces = cow
    uv, report = method(vertices, faces)
    assert uv.shape == (len(faces), 3, 2) and uv.dtype == np.float64 and np.isfinite(uv).all()
    assert report.method == method.__name__ and report.components == 1 and report.seam_edges > 0
    per_vertex = uvs_per_vertex(faces, uv)
    cut = [v for v, uvs in per_vertex.items() if len(uvs) > 1]
    # The vertices on the cut, no other, have a uv on each side: at most a few per seam edge.
    assert 0 < len(cut) <= 2 * report.seam_edges
    assert report.distortion.faces == len(faces)


def test_cut_methods_do_not_cut_a_disk_and_keep_polygons_whole():
    vertices, quads = quad_grid(6, 8)
    uv, report = norm_preserving.lscm(vertices, quads)
    assert uv.shape == (len(quads), 4, 2) and report.seam_edges == 0
    assert all(len(uvs) == 1 for uvs in uvs_per_vertex(quads, uv).values())  # one uv per vertex
    mixed = [list(q) for q in quads[1:]] + [list(quads[0][:3]), [quads[0][0], quads[0][2], quads[0][3]]]
    uv, _ = norm_preserving.arap(vertices, mixed)
    assert isinstance(uv, list) and [len(u) for u in uv] == [len(f) for f in mixed]


def test_ours_and_the_cut_methods_compare_in_three_lines(cow, cow_texture):
    """The doc's comparison, as a user writes it."""
    _, ours = cow_texture
    _, lscm = norm_preserving.lscm(*cow)
    _, arap = norm_preserving.arap(*cow)
    # The package's claim on the cow (README): lower length error than both, with no cut.
    assert ours.distortion.edge_length_error < arap.distortion.edge_length_error < lscm.distortion.edge_length_error


def test_measure_distortion_skips_the_faces_of_a_vertex_without_uv(cow, cow_texture):
    vertices, faces = cow
    uv = cow_texture[0].copy()
    uv[7] = np.nan
    measured = norm_preserving.measure_distortion(vertices, faces, uv)
    assert measured.faces == len(faces) - np.any(faces == 7, axis=1).sum()


def test_read_mesh_gives_arrays_or_lists_for_mixed_polygons(cow, tmp_path):
    vertices, faces = cow
    assert vertices.shape == (2904, 3) and vertices.dtype == np.float64
    assert faces.shape == (5804, 3) and faces.dtype == np.int64
    mixed = tmp_path / "mixed.off"
    mixed.write_text("OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0.5 0\n4 0 1 2 3\n3 1 4 2\n")
    vertices, faces = norm_preserving.read_mesh(mixed)
    assert vertices.shape == (5, 3) and [f.tolist() for f in faces] == [[0, 1, 2, 3], [1, 4, 2]]


def test_read_mesh_reads_a_ply_of_integer_coordinates(tmp_path):
    """Coordinates of integer types (which CGAL 5.5's reader crashes on), read by their type."""
    ply = tmp_path / "int.ply"
    ply.write_text("ply\nformat ascii 1.0\nelement vertex 3\nproperty int x\nproperty short y\nproperty uchar z\n"
                   "element face 1\nproperty list uchar int vertex_indices\nend_header\n-70000 0 0\n1 -300 0\n0 1 255\n"
                   "3 0 1 2\n")
    vertices, faces = norm_preserving.read_mesh(ply)
    assert vertices.tolist() == [[-70000, 0, 0], [1, -300, 0], [0, 1, 255]] and faces.tolist() == [[0, 1, 2]]


def test_read_mesh_reads_an_obj_with_lines_as_faces_of_two_corners(tmp_path):
    obj = tmp_path / "lines.obj"
    obj.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 2 0\nf 1 2 3\nl 3 4\nl 1 2 4\n")
    vertices, faces = norm_preserving.read_mesh(obj)
    assert vertices.shape == (4, 3) and [f.tolist() for f in faces] == [[0, 1, 2], [2, 3], [0, 1], [1, 3]]


def test_read_mesh_reads_ascii_and_binary_copies_of_a_ply_alike(tmp_path):
    """A float property reads the same from ASCII (rounded to float) as from binary (a float)."""
    header = ("ply\nformat {} 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 1\nproperty list uchar int vertex_indices\nend_header\n")
    coordinates = [0.1, 0.2, 0.3, 1 / 3, 2.0, -7.25, 1e-3, 5.5, 0.7]
    (tmp_path / "ascii.ply").write_text(header.format("ascii") + " ".join(map(repr, coordinates)) + "\n3 0 1 2\n")
    (tmp_path / "binary.ply").write_bytes(header.format("binary_big_endian").encode() +
                                          np.array(coordinates, dtype=">f4").tobytes() + b"\x03" +
                                          np.array([0, 1, 2], dtype=">i4").tobytes())
    ascii_vertices, _ = norm_preserving.read_mesh(tmp_path / "ascii.ply")
    binary_vertices, _ = norm_preserving.read_mesh(tmp_path / "binary.ply")
    expected = np.array(coordinates, dtype=np.float32).astype(np.float64).reshape(3, 3)
    assert np.array_equal(ascii_vertices, expected) and np.array_equal(binary_vertices, expected)


# (file name, content, the ValueError's expected words)
UNREADABLE = {
    "an index of 1e30": ("big.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                         "property float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n"
                         "0 0 0\n1 0 0\n0 1 0\n3 0 1e30 2\n",
                         "not a valid ply file: element tristrips, item 1 of 1, property vertex_indices: '1e30' is not a "
                         "value of type int"),
    "a PLY without z": ("no_z.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                        "element face 0\nproperty list uchar int vertex_indices\nend_header\n0 0\n",
                        "not a valid ply file: its vertices have no z coordinate"),
    "a PLY without faces": ("edges.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                            "property float z\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
                            "0 0 0\n1 0 0\n0 1\n", "the ply file has vertex and edge elements; no face element"),
    "an OBJ of points": ("points.obj", "v 0 0 0\nv 1 0 0\n", "the obj file has no face"),
    "an OBJ index out of range": ("far.obj", "v 0 0 0\nf 1 2 3\n", "not a valid obj file: line 2: vertex 2 of 1"),
    "garbage OFF": ("garbage.off", "this is no mesh\n", "not a valid off file"),
    "an empty file": ("empty.stl", "", "the file is empty"),
    "no mesh format": ("mesh.xyz", "0 0 0\n", "not a mesh format: .xyz"),
}


@pytest.mark.parametrize("name, content, message", UNREADABLE.values(), ids=UNREADABLE.keys())
def test_read_mesh_raises_value_error_with_the_readers_message(tmp_path, name, content, message):
    path = tmp_path / name
    path.write_text(content)
    with pytest.raises(ValueError, match=re.escape(f"cannot read {path}: {message}")):
        norm_preserving.read_mesh(path)


def test_write_obj_writes_what_read_mesh_reads_back(cow, cow_texture, tmp_path):
    vertices, faces = cow
    uv = cow_texture[0]
    norm_preserving.write_obj(str(tmp_path / "cow"), vertices, faces, uv)
    read_vertices, read_faces = norm_preserving.read_mesh(tmp_path / "cow.obj")
    assert np.array_equal(read_vertices, vertices) and np.array_equal(read_faces, faces)
    lines = (tmp_path / "cow.obj").read_text().splitlines()
    written_uv = np.array([[float(x) for x in line.split()[1:]] for line in lines if line.startswith("vt ")])
    assert np.array_equal(written_uv, uv)  # 17 digits: the doubles themselves
    assert (tmp_path / "cow.mtl").read_text().split()[-1] == "cow.png"
    assert (tmp_path / "cow.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cow.mtl", "cow.obj", "cow.png"]  # no scratch left


def soup_with_a_line_and_a_lone_vertex():
    """Two triangles, a face of two corners (a line) and a vertex on no face: texture()'s NaN."""
    vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.5], [3, 3, 3]], dtype=float)
    faces = [[0, 1, 2], [0, 2, 3], [1, 3]]
    uv, report = norm_preserving.texture(vertices, faces)
    assert report.isolated_vertices == 1 and np.isnan(uv[4]).all()
    return vertices, faces, uv


def test_write_obj_takes_a_basename_with_obj_and_writes_a_vertex_without_uv_at_the_origin(tmp_path):
    vertices, faces, uv = soup_with_a_line_and_a_lone_vertex()
    norm_preserving.write_obj(tmp_path / "soup.OBJ", vertices, faces, uv)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["soup.mtl", "soup.obj", "soup.png"]
    lines = (tmp_path / "soup.obj").read_text().splitlines()
    assert lines[0] == "mtllib soup.mtl" and [l for l in lines if l.startswith("vt ")][-1] == "vt 0 0"
    assert [l for l in lines if l[0] in "fl"] == ["f 1/1 2/2 3/3", "f 1/1 3/3 4/4", "l 2/2 4/4"]
    read_vertices, read_faces = norm_preserving.read_mesh(tmp_path / "soup.obj")
    assert np.array_equal(read_vertices, vertices) and [f.tolist() for f in read_faces] == faces


def test_write_obj_refuses_a_non_finite_vertex_and_writes_nothing(tmp_path):
    vertices, faces, uv = soup_with_a_line_and_a_lone_vertex()
    vertices[4, 2] = np.inf
    with pytest.raises(ValueError, match="vertex 4 is on no face and has a non-finite coordinate"):
        norm_preserving.write_obj(tmp_path / "soup", vertices, faces, uv)
    vertices[4, 2], vertices[1, 0] = 3, np.nan
    with pytest.raises(ValueError, match="^vertex 1 has a non-finite coordinate"):
        norm_preserving.write_obj(tmp_path / "soup", vertices, faces, uv)
    assert list(tmp_path.iterdir()) == []


def test_write_obj_writes_all_three_files_or_none(tmp_path):
    """A file that cannot be written (here a directory stands where soup.png goes): OSError, and
    neither the OBJ nor the MTL is written, nor a scratch directory left; older files stay."""
    vertices, faces, uv = soup_with_a_line_and_a_lone_vertex()
    (tmp_path / "soup.obj").write_text("an older file\n")
    (tmp_path / "soup.png").mkdir()
    with pytest.raises(OSError, match="cannot write .*soup.obj, .mtl, .png: .*soup.png is a directory; nothing written"):
        norm_preserving.write_obj(tmp_path / "soup", vertices, faces, uv)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["soup.obj", "soup.png"]
    assert (tmp_path / "soup.obj").read_text() == "an older file\n"
    with pytest.raises(OSError, match="no such directory"):
        norm_preserving.write_obj(tmp_path / "missing" / "soup", vertices, faces, uv)
    with pytest.raises(ValueError, match="the basename must end in a file name"):
        norm_preserving.write_obj(str(tmp_path) + "/", vertices, faces, uv)


def readme_python_blocks():
    """The ```python blocks of the README, as a user copies them."""
    readme = pathlib.Path(os.environ.get("NP_README", pathlib.Path(__file__).parents[2] / "README.md")).read_text()
    blocks = re.findall(r"^( *)```python\n(.*?)^\1```", readme, re.MULTILINE | re.DOTALL)
    return [textwrap.dedent(code) for _, code in blocks]


def test_the_readme_example_textures_the_cow_and_writes_an_obj(tmp_path):
    """The README's Python example, run as a user would from the repository's root, where it reads
    build/data/meshes/cow.off: here a directory whose build/data/meshes is the build's meshes."""
    blocks = readme_python_blocks()
    assert len(blocks) == 1 and "norm_preserving.texture(" in blocks[0], blocks
    (tmp_path / "build" / "data").mkdir(parents=True)
    (tmp_path / "build" / "data" / "meshes").symlink_to(mesh_path("cow").parent.resolve(), target_is_directory=True)
    run = subprocess.run([sys.executable, "-c", blocks[0]], cwd=tmp_path, env=os.environ, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert run.stdout.startswith("objective ")
    obj = (tmp_path / "cow_textured.obj").read_text()
    assert obj.count("\nv ") == obj.count("\nvt ") == 2904 and obj.count("\nf ") == 5804
    assert (tmp_path / "cow_textured.png").exists()
