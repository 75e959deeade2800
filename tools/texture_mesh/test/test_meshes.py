"""Meshes for the command-line tool's tests, made at test time from a triangle mesh in OFF (CGAL's
cow), and checks of what the tool read from them and wrote. Run by Debian's /usr/bin/python3
(and imported by blender/test/blender_addon_check.py for write_obj()):

  test_meshes.py strips IN.off OUT.ply FORMAT
      IN's triangles as triangle strips, the way many of Stanford's scans store their faces:
      `element tristrips`, each item a list of strips with -1 between them, each triangle after
      the first of a strip reversed (ply FORMAT: ascii, binary_little_endian or binary_big_endian)
  test_meshes.py obj IN.off OUT.obj
      IN as an OBJ file
  test_meshes.py same-triangles IN.off OUT.obj
      exit 1 unless the faces of OUT (the tool's output) are IN's triangles, each with its
      orientation (a triangle reversed reads as another triangle)
  test_meshes.py ply-triangle OUT.ply FORMAT
      a triangle whose x, y and z are a short, an int and a double, with the extremes of each
      integer type: (0, 0, 0), (32767, -2147483648, 0.5), (-32768, 2147483647, -2.5)
  test_meshes.py check-strips IN.off OUT.obj...
      same-triangles for each OUT, then exit 1 unless the OUTs are the same bytes, but for the
      name of their MTL file (the tool's OBJs of ASCII and binary copies of one PLY)
  test_meshes.py check-glb FILE.glb...
      exit 1 unless each glb is well-formed, checked offline: the header's and the chunks'
      lengths, 4-byte aligned chunks and buffer views within the buffer, accessors within their
      views, POSITION's min and max those of the data, every index below the vertex count and
      a whole number of triangles or lines, unit normals, and the image's MIME type that of its
      bytes
"""

import collections
import json
import math
import struct
import sys


def read_off(path):
    words = open(path).read().split()
    if words[0] != "OFF":
        sys.exit(f"{path}: not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    at = 4
    points = [tuple(float(w) for w in words[at + 3 * i:at + 3 * i + 3]) for i in range(nv)]
    at += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(words[at])
        faces.append(tuple(int(w) for w in words[at + 1:at + 1 + n]))
        at += 1 + n
    if any(len(f) != 3 for f in faces):
        sys.exit(f"{path}: the strips are made of triangles only")
    return points, faces


def strip_triangles(strip):
    """The triangles of one strip, as the PLY reader must read them."""
    return [(strip[k], strip[k + 1], strip[k + 2]) if k % 2 == 0 else (strip[k + 1], strip[k], strip[k + 2])
            for k in range(len(strip) - 2)]


def make_strips(faces):
    """Greedy strips covering every triangle once: a strip grows while a triangle not used yet
    has the directed edge its next position needs."""
    by_edge = collections.defaultdict(list)  # directed edge (a, b) -> triangles (a, b, c) up to rotation
    for t, (a, b, c) in enumerate(faces):
        for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
            by_edge[(u, v)].append((t, w))
    used = [False] * len(faces)
    strips = []
    for t, face in enumerate(faces):
        if used[t]:
            continue
        used[t] = True
        strip = list(face)
        while True:
            k = len(strip) - 2  # the position of the next triangle
            edge = (strip[-2], strip[-1]) if k % 2 == 0 else (strip[-1], strip[-2])
            following = next(((u, w) for u, w in by_edge[edge] if not used[u]), None)
            if following is None:
                break
            used[following[0]] = True
            strip.append(following[1])
        strips.append(strip)
    return strips


def write_strips(points, faces, path, fmt):
    strips = make_strips(faces)
    lists = [[]]  # items of the tristrips element: a few strips each, -1 between them
    for strip in strips:
        if len(lists[-1]) > 200:
            lists.append([])
        lists[-1].extend(([-1] if lists[-1] else []) + strip)
    made = collections.Counter(oriented(t) for s in strips for t in strip_triangles(s))
    assert made == collections.Counter(oriented(f) for f in faces), "the strips are not the triangles"
    header = (f"ply\nformat {fmt} 1.0\ncomment {len(strips)} strips\nelement vertex {len(points)}\n"
              "property float x\nproperty float y\nproperty float z\n"
              f"element tristrips {len(lists)}\nproperty list int int vertex_indices\nend_header\n")
    with open(path, "wb") as out:
        out.write(header.encode())
        if fmt == "ascii":
            out.write("".join(f"{x!r} {y!r} {z!r}\n" for x, y, z in points).encode())
            out.write("".join(f"{len(l)} {' '.join(map(str, l))}\n" for l in lists).encode())
        else:
            order = "<" if fmt == "binary_little_endian" else ">"
            for p in points:
                out.write(struct.pack(order + "3f", *p))
            for l in lists:
                out.write(struct.pack(f"{order}i{len(l)}i", len(l), *l))
    print(f"{path}: {len(faces)} triangles in {len(strips)} strips, {len(lists)} lists")


def write_obj(points, faces, path):
    """An OBJ of the vertices (17 digits: the doubles themselves) and faces, nothing else."""
    with open(path, "w") as out:
        out.write("".join(f"v {x!r} {y!r} {z!r}\n" for x, y, z in points))
        out.write("".join("f " + " ".join(str(i + 1) for i in face) + "\n" for face in faces))


def write_ply_triangle(path, fmt):
    points = [(0, 0, 0.0), (32767, -2147483648, 0.5), (-32768, 2147483647, -2.5)]
    header = (f"ply\nformat {fmt} 1.0\nelement vertex 3\nproperty short x\nproperty int y\nproperty double z\n"
              "element face 1\nproperty list uchar int vertex_indices\nend_header\n")
    with open(path, "wb") as out:
        out.write(header.encode())
        if fmt == "ascii":
            out.write("".join(f"{x} {y} {z!r}\n" for x, y, z in points).encode() + b"3 0 1 2\n")
        else:
            order = "<" if fmt == "binary_little_endian" else ">"
            for p in points:
                out.write(struct.pack(order + "hid", *p))
            out.write(struct.pack(order + "B3i", 3, 0, 1, 2))


def same_obj(paths):
    """The tool's OBJ files are the same bytes, but for their first line, which names their MTL."""
    first = None
    for path in paths:
        lines = open(path, "rb").read().split(b"\n", 1)
        stem = path.rsplit("/", 1)[-1][:-len(".obj")]
        if lines[0] != f"mtllib {stem}.mtl".encode():
            sys.exit(f"{path}: the first line is {lines[0]!r}, not its MTL")
        if first is None:
            first = (path, lines[1])
        elif lines[1] != first[1]:
            sys.exit(f"{path} and {first[0]} differ")
    print(f"{len(paths)} OBJ files, the same bytes: {', '.join(paths)}")


COMPONENTS = {5120: ("b", 1), 5121: ("B", 1), 5122: ("h", 2), 5123: ("H", 2), 5125: ("I", 4), 5126: ("f", 4)}
SIZES = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}


def check_glb(path):
    """Raises AssertionError with what is wrong with the glb `path`, if anything."""
    data = open(path, "rb").read()
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    assert magic == b"glTF" and version == 2, f"header {magic!r} version {version}"
    assert length == len(data), f"the header's length {length}, the file's {len(data)}"
    chunks, at = [], 12
    while at < len(data):
        chunk_length, chunk_type = struct.unpack_from("<I4s", data, at)
        assert chunk_length % 4 == 0, f"chunk {chunk_type!r} of {chunk_length} bytes, not a multiple of 4"
        assert at + 8 + chunk_length <= len(data), f"chunk {chunk_type!r} runs past the end"
        chunks.append((chunk_type, data[at + 8:at + 8 + chunk_length]))
        at += 8 + chunk_length
    assert at == len(data) and [c[0] for c in chunks] == [b"JSON", b"BIN\0"], [c[0] for c in chunks]
    gltf, binary = json.loads(chunks[0][1]), chunks[1][1]
    buffer_length = gltf["buffers"][0]["byteLength"]
    assert buffer_length <= len(binary) < buffer_length + 4, f"buffer of {buffer_length} bytes in a chunk of {len(binary)}"
    views = gltf["bufferViews"]
    for k, view in enumerate(views):
        offset = view.get("byteOffset", 0)
        assert offset % 4 == 0, f"bufferView {k} at byte {offset}, not 4-byte aligned"
        assert offset + view["byteLength"] <= buffer_length, f"bufferView {k} runs past the buffer"

    def accessor_values(index):
        accessor = gltf["accessors"][index]
        view = views[accessor["bufferView"]]
        code, size = COMPONENTS[accessor["componentType"]]
        width = SIZES[accessor["type"]]
        start = view.get("byteOffset", 0) + accessor.get("byteOffset", 0)
        assert (start % size == 0 and accessor.get("byteOffset", 0) + accessor["count"] * width * size
                <= view["byteLength"]), f"accessor {index} runs past its view"
        flat = struct.unpack_from(f"<{accessor['count'] * width}{code}", binary, start)
        return accessor, [flat[i:i + width] for i in range(0, len(flat), width)]

    for mesh in gltf["meshes"]:
        for primitive in mesh["primitives"]:
            attributes = primitive["attributes"]
            accessor, positions = accessor_values(attributes["POSITION"])
            for c, (low, high) in enumerate(zip(accessor["min"], accessor["max"])):
                values = [p[c] for p in positions]
                assert (low, high) == (min(values), max(values)), \
                    f"POSITION's min and max {low}, {high} on axis {c}, the data's {min(values)}, {max(values)}"
            _, normals = accessor_values(attributes["NORMAL"])
            worst = max(abs(math.sqrt(sum(x * x for x in n)) - 1) for n in normals)
            assert len(normals) == len(positions) and worst < 1e-6, f"a normal's length is 1 +- {worst}"
            _, uvs = accessor_values(attributes["TEXCOORD_0"])
            assert len(uvs) == len(positions) and all(math.isfinite(x) for uv in uvs for x in uv), "uvs"
            if "indices" in primitive:
                _, indices = accessor_values(primitive["indices"])
                indices = [i[0] for i in indices]
                corners = {4: 3, 1: 2}.get(primitive.get("mode", 4), 1)
                assert len(indices) % corners == 0, f"{len(indices)} indices for mode {primitive.get('mode', 4)}"
                assert max(indices) < len(positions), f"index {max(indices)} of {len(positions)} vertices"
    for image in gltf["images"]:
        view = views[image["bufferView"]]
        start = view.get("byteOffset", 0)
        signature = binary[start:start + 8]
        actual = ("image/png" if signature == b"\x89PNG\r\n\x1a\n" else
                  "image/jpeg" if signature[:3] == b"\xff\xd8\xff" else "neither PNG nor JPEG")
        assert image["mimeType"] == actual, f"the image is {actual}, its mimeType {image['mimeType']}"
    return gltf


def check_glbs(paths):
    failed = False
    for path in paths:
        try:
            gltf = check_glb(path)
            print(f"{path}: well-formed, {gltf['accessors'][0]['count']} vertices")
        except (AssertionError, KeyError, IndexError, struct.error, ValueError) as e:
            print(f"{path}: {type(e).__name__}: {e}")
            failed = True
    if failed or not paths:
        sys.exit(1)


def oriented(triangle):
    """The triangle with its smallest index first, its orientation kept."""
    k = triangle.index(min(triangle))
    return triangle[k:] + triangle[:k]


def same_triangles(off_path, obj_path):
    _, faces = read_off(off_path)
    read = []
    for line in open(obj_path):
        if line.startswith("f "):
            read.append(tuple(int(corner.split("/")[0]) - 1 for corner in line.split()[1:]))
    expected = collections.Counter(oriented(f) for f in faces)
    found = collections.Counter(oriented(f) for f in read)
    if expected != found:
        missing, extra = expected - found, found - expected
        sys.exit(f"{obj_path}: {len(read)} faces; {sum(missing.values())} triangles of {off_path} missing "
                 f"(e.g. {list(missing)[:3]}), {sum(extra.values())} not in it (e.g. {list(extra)[:3]})")
    print(f"{obj_path}: the {len(faces)} triangles of {off_path}, each with its orientation")


if __name__ == "__main__":
    command, arguments = sys.argv[1], sys.argv[2:]
    if command == "strips":
        write_strips(*read_off(arguments[0]), arguments[1], arguments[2])
    elif command == "obj":
        write_obj(*read_off(arguments[0]), arguments[1])
    elif command == "same-triangles":
        same_triangles(*arguments)
    elif command == "ply-triangle":
        write_ply_triangle(*arguments)
    elif command == "check-strips":
        for obj in arguments[1:]:
            same_triangles(arguments[0], obj)
        same_obj(arguments[1:])
    elif command == "check-glb":
        check_glbs(arguments)
    else:
        sys.exit(__doc__)
