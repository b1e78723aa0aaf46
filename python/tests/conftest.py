"""Shared fixtures: small meshes made here, and the paths of the project and its shared meshes."""

import os
import pathlib

import numpy as np
import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("RAYLAB_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SHARED_SCENES = SOURCE_DIR.parent / "shared" / "scenes"


def icosphere(level=2, radius=1.0):
    """A closed, consistently wound icosphere as (vertices float32 (N,3), triangles uint32 (M,3))."""
    t = (1.0 + 5.0**0.5) / 2.0
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
         (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
         (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
         (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    verts = [np.array(p, dtype=np.float64) / np.linalg.norm(p) for p in v]
    for _ in range(level):
        cache = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                m = verts[a] + verts[b]
                verts.append(m / np.linalg.norm(m))
                cache[key] = len(verts) - 1
            return cache[key]

        nf = []
        for a, b, c in f:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = nf
    return (np.array(verts) * radius).astype(np.float32), np.array(f, dtype=np.uint32)


def is_closed(triangles):
    """Whether every undirected edge is shared by exactly two triangles."""
    e = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    e.sort(axis=1)
    _, counts = np.unique(e, axis=0, return_counts=True)
    return bool(np.all(counts == 2))


@pytest.fixture
def sphere():
    return icosphere(2)


@pytest.fixture
def binary():
    """The command line in the build tree (for answers of the C++ side)."""
    path = os.environ.get("RAYLAB_BINARY")
    if not path or not os.path.exists(path):
        pytest.skip("RAYLAB_BINARY not set")
    return path


@pytest.fixture(scope="session", autouse=True)
def tested_package_is_the_expected_one():
    """Where RAYLAB_EXPECT_PACKAGE_UNDER names a folder (the wheel test, tests/install/wheel_test.sh),
    the raylab under test must have been imported from it, not from a source or build tree."""
    expected = os.environ.get("RAYLAB_EXPECT_PACKAGE_UNDER")
    if expected:
        import raylab

        where = pathlib.Path(raylab.__file__).resolve()
        assert where.is_relative_to(pathlib.Path(expected).resolve()), f"raylab imported from {where}, not under {expected}"
