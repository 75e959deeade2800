"""The add-on's zip, as built: check_zip.py <norm_preserving_unwrap-VERSION-linux-x86_64.zip>

Checks that it holds the add-on as a package (norm_preserving_unwrap/__init__.py, whose bl_info
Blender 4.1 and earlier read), the manifest of Blender 4.2's extensions, with the add-on's id and
version, and the module built for Python 3.11 on x86-64; and that the module's dynamic
dependencies (readelf -d) are the C and C++ runtime alone. Any failed check raises."""

import ast
import pathlib
import re
import subprocess
import sys
import tempfile
import tomllib
import zipfile

RUNTIME = {"libc.so.6", "libm.so.6", "libstdc++.so.6", "libgcc_s.so.1", "ld-linux-x86-64.so.2"}

path = pathlib.Path(sys.argv[1])
with zipfile.ZipFile(path) as archive:
    names = set(archive.namelist())
    modules = [n for n in names if re.fullmatch(r"norm_preserving_unwrap/norm_preserving\.cpython-311-x86_64-linux-gnu\.so", n)]
    assert len(modules) == 1, f"no module for Python 3.11 on x86-64 in {sorted(names)}"
    assert {"norm_preserving_unwrap/__init__.py", "norm_preserving_unwrap/blender_manifest.toml"} <= names, sorted(names)
    assert all(n.startswith("norm_preserving_unwrap/") for n in names), sorted(names)
    manifest = tomllib.loads(archive.read("norm_preserving_unwrap/blender_manifest.toml").decode())
    addon = archive.read("norm_preserving_unwrap/__init__.py").decode()
    with tempfile.TemporaryDirectory() as scratch:
        module = archive.extract(modules[0], scratch)
        dynamic = subprocess.run(["readelf", "-d", module], check=True, capture_output=True, text=True).stdout

needed = set(re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", dynamic))
assert needed, f"readelf -d lists no library:\n{dynamic}"
assert needed <= RUNTIME, f"the module needs libraries beyond the C and C++ runtime: {sorted(needed - RUNTIME)}"

bl_info = ast.literal_eval(re.search(r"^bl_info = (\{.*?^\})", addon, re.M | re.S).group(1))
version = ".".join(map(str, bl_info["version"]))
assert path.name == f"norm_preserving_unwrap-{version}-linux-x86_64.zip", (path.name, version)
expected = {"schema_version": "1.0.0", "id": "norm_preserving_unwrap", "version": version, "type": "add-on",
            "platforms": ["linux-x64"], "license": ["SPDX:GPL-3.0-or-later"]}
for key, value in expected.items():
    assert manifest.get(key) == value, f"manifest {key}: {manifest.get(key)!r}, expected {value!r}"
assert tuple(map(int, manifest["blender_version_min"].split("."))) >= (4, 2, 0), manifest["blender_version_min"]
assert len(manifest["tagline"]) <= 64 and not manifest["tagline"].endswith((".", "!", "?")), manifest["tagline"]
print(f"check_zip: {path.name}: the module needs {', '.join(sorted(needed))}; manifest {manifest['id']} {version}")
