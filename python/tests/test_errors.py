"""Bad input raises an exception naming the argument; it never crashes."""

import numpy as np
import pytest

import raylab


@pytest.fixture
def tri():
    return np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], np.float32), np.array([[0, 1, 2]], np.uint32)


def test_mesh_shapes_and_dtypes(tri):
    v, f = tri
    with pytest.raises(ValueError, match=r"vertices: expected shape \(N, 3\), got \(3, 2\)"):
        raylab.Mesh(v[:, :2], f)
    with pytest.raises(ValueError, match=r"triangles: expected shape \(N, 3\)"):
        raylab.Mesh(v, f.ravel())
    with pytest.raises(TypeError, match="triangles: expected an array of integers"):
        raylab.Mesh(v, f.astype(np.float32))
    with pytest.raises(TypeError, match="vertices"):
        raylab.Mesh("not an array", f)
    with pytest.raises(TypeError, match="vertices"):
        raylab.Mesh(np.array([["a", "b", "c"]]), f)


def test_mesh_values(tri):
    v, f = tri
    with pytest.raises(ValueError, match="triangles: triangle 0 refers to vertex 3, but there are 3 vertices"):
        raylab.Mesh(v, np.array([[0, 1, 3]], np.uint32))
    with pytest.raises(ValueError, match=r"triangles: vertex indices must lie in \[0, 2\^32\)"):
        raylab.Mesh(v, np.array([[0, 1, -1]]))
    bad = v.copy()
    bad[1, 2] = np.nan
    with pytest.raises(ValueError, match="vertices: vertex 1"):
        raylab.Mesh(bad, f)
    with pytest.raises(ValueError, match="vertices: vertex 2"):
        raylab.Mesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1e300, 0]]), f)


def test_query_shapes(tri):
    scene = raylab.Mesh(*tri)
    o = np.zeros((4, 3), np.float32)
    with pytest.raises(ValueError, match=r"rays: expected shape \(\.\.\., 6\), got \(4, 3\)"):
        scene.intersect(o)
    with pytest.raises(ValueError, match="directions: shape does not match origins"):
        scene.intersect(o, np.ones((5, 3), np.float32))
    with pytest.raises(ValueError, match=r"directions: expected shape \(\.\.\., 3\)"):
        scene.occluded(o, np.ones((4, 2), np.float32))
    with pytest.raises(TypeError, match="origins"):
        scene.count_intersections(object(), o)
    with pytest.raises(ValueError, match=r"points: expected shape \(\.\.\., 3\)"):
        scene.contains(np.zeros((3, 4)))
    with pytest.raises(ValueError, match="threads"):
        scene.intersect(o, o, threads=0)
    with pytest.raises(ValueError, match="NaN"):
        scene.intersect(o, o, tmin=float("nan"))


def test_rays_that_are_not_finite_miss(tri):
    scene = raylab.Mesh(*tri)
    o = np.array([[0.2, 0.2, 1], [np.nan, 0, 1], [0.2, 0.2, 1], [0.2, 0.2, 1]], np.float32)
    d = np.array([[0, 0, -1], [0, 0, -1], [0, 0, 0], [np.inf, 0, -1]], np.float32)
    hits = scene.intersect(o, d)
    assert hits["prim_id"][0] == 0 and hits["t"][0] == 1.0
    assert np.all(hits["prim_id"][1:] == -1)


def test_build_names_and_parameters(tri):
    scene = raylab.Mesh(*tri)
    with pytest.raises(ValueError, match="octree"):
        scene.build("kdtree")
    with pytest.raises(TypeError, match="takes no parameter 'density'; it takes: .*max_leaf_size"):
        scene.build("bvh", density=3)
    with pytest.raises(TypeError, match="spatial_splits"):
        scene.build("bvh", spatial_splits="yes")
    assert scene.build("grid", density=2.0) is scene
    assert scene.accel == "grid" and scene.info["name"] == "grid"
    assert "bvh" in raylab.accelerators()


def test_broken_scene_file_raises_scene_error_with_its_position(tmp_path):
    path = tmp_path / "broken.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")
    with pytest.raises(raylab.SceneError) as error:
        raylab.load(path)
    assert error.value.file.endswith("broken.obj")
    assert error.value.line == 4 and error.value.column > 0
    assert isinstance(error.value, ValueError)
    with pytest.raises(raylab.SceneError):
        raylab.load(tmp_path / "missing.obj")
    with pytest.raises(ValueError, match="unsupported scene format"):
        raylab.load(tmp_path / "scene.xyz")


def test_outside_paths_are_refused_naming_the_keyword(tmp_path):
    (tmp_path / "inner").mkdir()
    (tmp_path / "tri.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    scene_file = tmp_path / "inner" / "scene.json"
    scene_file.write_text('{"version": 1, "objects": [{"type": "mesh", "file": "../tri.obj"}]}')
    with pytest.raises(raylab.SceneError, match="allow_outside_paths=True") as error:
        raylab.load(scene_file)
    assert error.value.file.endswith("scene.json") and error.value.line > 0
    assert raylab.load(scene_file, allow_outside_paths=True).primitive_count == 1
