"""Fixtures of the norm_preserving module's tests (ctest python_module runs them on the module of
the build tree, with Debian's python3 and pytest): CGAL's meshes, read once."""

import os
import pathlib

import pytest

import norm_preserving

MESH_DIR = pathlib.Path(os.environ.get("NP_MESH_DIR", "build/data/meshes"))


def mesh_path(name):
    """The path of one of CGAL's meshes, extracted into the build tree at configure time."""
    path = MESH_DIR / f"{name}.off"
    if not path.exists():
        pytest.fail(f"{path} not found: set NP_MESH_DIR to <build>/data/meshes (ctest does)")
    return path


@pytest.fixture(scope="session")
def cow():
    """(vertices, faces) of the cow: a closed triangle mesh of 2,904 vertices."""
    return norm_preserving.read_mesh(mesh_path("cow"))


@pytest.fixture(scope="session")
def cow_texture(cow):
    """(uv, report) of texture() on the cow with the default options, solved once for the session;
    the uv array is read-only (a test that changes it changes a copy)."""
    uv, report = norm_preserving.texture(*cow)
    uv.flags.writeable = False
    return uv, report


@pytest.fixture(scope="session")
def bunny():
    """(vertices, faces) of bunny00: a closed triangle mesh of 37,706 vertices."""
    return norm_preserving.read_mesh(mesh_path("bunny00"))


def quad_grid(rows, columns):
    """A disk of rows x columns quads on a wavy height field: (vertices (n, 3), faces (m, 4))."""
    import numpy as np

    x, y = np.meshgrid(np.arange(columns + 1, dtype=float), np.arange(rows + 1, dtype=float))
    vertices = np.stack([x.ravel(), y.ravel(), 0.3 * np.sin(x.ravel()) * np.cos(y.ravel())], axis=1)
    corner = (np.arange(rows)[:, None] * (columns + 1) + np.arange(columns)[None, :]).ravel()
    faces = np.stack([corner, corner + 1, corner + columns + 2, corner + columns + 1], axis=1)
    return vertices, faces
