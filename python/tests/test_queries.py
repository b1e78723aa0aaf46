"""Ray queries from Python: answers against brute force and against the C++ side, shapes,
thread-count independence, and the inside/outside counting on closed meshes."""

import subprocess

import numpy as np
import pytest

import raylab
from conftest import SHARED_SCENES, icosphere, is_closed


def random_rays(n, seed, radius=3.0, target=1.5):
    rng = np.random.default_rng(seed)
    o = rng.normal(size=(n, 3))
    o = (o / np.linalg.norm(o, axis=1, keepdims=True) * radius).astype(np.float32)
    d = (rng.uniform(-target, target, size=(n, 3)) - o).astype(np.float32)
    return o, d


def brute_force(vertices, triangles, o, d):
    """Closest hit by Moller-Trumbore in float64, for every ray and triangle (small meshes only)."""
    p0, p1, p2 = (vertices[triangles[:, k]].astype(np.float64) for k in range(3))
    e1, e2 = p1 - p0, p2 - p0
    t_best = np.full(len(o), np.inf)
    id_best = np.full(len(o), -1)
    for i in range(len(o)):
        dv = d[i].astype(np.float64)
        p = np.cross(dv, e2)
        det = np.einsum("ij,ij->i", e1, p)
        s = o[i] - p0
        u = np.einsum("ij,ij->i", s, p) / det
        q = np.cross(s, e1)
        v = (q @ dv) / det
        t = np.einsum("ij,ij->i", e2, q) / det
        ok = (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0)
        if ok.any():
            k = np.argmin(np.where(ok, t, np.inf))
            t_best[i], id_best[i] = t[k], k
    return t_best, id_best


def test_intersect_agrees_with_brute_force(sphere):
    v, f = sphere
    scene = raylab.Mesh(v, f).build("bvh")
    o, d = random_rays(400, 1)
    hits = scene.intersect(o, d)
    t_ref, id_ref = brute_force(v, f, o, d)
    assert set(hits) == {"t", "prim_id", "object_id", "uv", "normal"}
    assert hits["t"].dtype == np.float32 and hits["prim_id"].dtype == np.int32
    hit = np.isfinite(t_ref)
    assert hit.sum() > 100  # the ball fills about 40% of the targets' cube
    np.testing.assert_array_equal(np.isfinite(hits["t"]), hit)
    np.testing.assert_allclose(hits["t"][hit], t_ref[hit], rtol=1e-5)
    # Away from edges (where float and double may pick different neighbours) the ids agree.
    agree = hits["prim_id"][hit] == id_ref[hit]
    assert agree.mean() > 0.99
    assert np.all(hits["prim_id"][~hit] == -1) and np.all(hits["object_id"][~hit] == -1)
    assert np.all(hits["object_id"][hit] == 0)
    n = hits["normal"][hit]
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1.0, rtol=1e-5)
    # As wound: the icosphere's triangles face outward.
    points = o[hit] + hits["t"][hit, None] * d[hit]
    assert np.all(np.einsum("ij,ij->i", n, points) > 0)
    uv = hits["uv"][hit]
    assert np.all(uv >= 0) and np.all(uv.sum(axis=1) <= 1 + 1e-6)


def test_leading_shape_is_kept_and_six_column_rays_are_accepted(sphere):
    scene = raylab.Mesh(*sphere)
    rays = raylab.pinhole_rays(32, 24, eye=(0, 0, 4), at=(0, 0, 0), fov=40)
    assert rays.shape == (24, 32, 6) and rays.dtype == np.float32
    hits = scene.intersect(rays)
    assert hits["t"].shape == (24, 32) and hits["uv"].shape == (24, 32, 2) and hits["normal"].shape == (24, 32, 3)
    split = scene.intersect(rays[..., :3], rays[..., 3:])
    np.testing.assert_array_equal(split["t"], hits["t"])
    flat = scene.intersect(rays.reshape(-1, 6))
    np.testing.assert_array_equal(flat["prim_id"].reshape(24, 32), hits["prim_id"])
    # The centre ray hits the unit sphere about 3 units away (the icosphere lies within it).
    assert 3.0 <= hits["t"][12, 16] < 3.02
    assert scene.occluded(rays).shape == (24, 32)
    assert scene.count_intersections(rays).shape == (24, 32)


def test_tmin_and_tmax_limit_the_rays(sphere):
    scene = raylab.Mesh(*sphere)
    o = np.array([[0, 0, 4]], np.float32)
    d = np.array([[0, 0, -1]], np.float32)
    near = scene.intersect(o, d)["t"][0]
    assert scene.intersect(o, d, tmax=near)["t"][0] == np.inf
    far = scene.intersect(o, d, tmin=near + 0.01)["t"][0]
    assert 4.9 < far < 5.01
    assert not scene.occluded(o, d, tmax=2.0)[0] and scene.occluded(o, d)[0]
    assert scene.count_intersections(o, d)[0] == 2 and scene.count_intersections(o, d, tmin=4.5)[0] == 1


def test_answers_equal_the_cpp_command_line_on_the_same_rays(tmp_path, binary):
    mesh = SHARED_SCENES / "stanford-bunny.obj"
    if not mesh.exists():
        pytest.skip("shared meshes not present")
    scene = raylab.load(mesh)
    lo, hi = scene.bounds
    rng = np.random.default_rng(3)
    n = 20000
    o = rng.uniform(lo - (hi - lo), hi + (hi - lo), size=(n, 3)).astype(np.float32)
    d = (rng.uniform(lo, hi, size=(n, 3)) - o).astype(np.float32)
    records = np.zeros((n, 8), np.float32)
    records[:, 0:3], records[:, 4:7], records[:, 7] = o, d, np.inf
    rays_file, hits_file = tmp_path / "r.rays", tmp_path / "h.hits"
    records.tofile(rays_file)
    subprocess.run([binary, "bench", str(mesh), "--rays-file", str(rays_file), "--hits-out", str(hits_file),
                    "--against", "none", "--repeats", "1", "--allow-outside-paths"],
                   check=True, capture_output=True)
    expected = np.fromfile(hits_file, dtype=np.dtype([("t", "<f4"), ("id", "<u4")]))
    hits = scene.intersect(o, d)
    np.testing.assert_array_equal(hits["t"], expected["t"])
    np.testing.assert_array_equal(hits["prim_id"].astype(np.int64) & 0xFFFFFFFF, expected["id"])
    assert np.isfinite(hits["t"]).sum() > n // 10


@pytest.mark.parametrize("accel", ["bvh", "bvh2", "grid", "grid2", "octree", "irregular", "brute"])
def test_every_structure_gives_the_same_answers(sphere, accel):
    v, f = sphere
    o, d = random_rays(2000, 4)
    reference = raylab.Mesh(v, f).build("brute").intersect(o, d)
    hits = raylab.Mesh(v, f).build(accel).intersect(o, d)
    np.testing.assert_array_equal(hits["t"], reference["t"])
    np.testing.assert_array_equal(hits["prim_id"], reference["prim_id"])


def test_answers_do_not_depend_on_the_thread_count(sphere):
    scene = raylab.Mesh(*sphere)
    o, d = random_rays(100000, 5)
    one = scene.intersect(o, d, threads=1)
    two = scene.intersect(o, d, threads=2)
    for key in one:
        np.testing.assert_array_equal(one[key], two[key])
    np.testing.assert_array_equal(scene.occluded(o, d, threads=1), scene.occluded(o, d, threads=2))
    np.testing.assert_array_equal(scene.count_intersections(o, d, threads=1), scene.count_intersections(o, d))


def closed_meshes():
    yield "icosphere", *icosphere(3)
    for name in ["armadillo.off", "stanford-bunny.obj", "nefertiti.obj", "igea.ply"]:
        path = SHARED_SCENES / name
        if path.exists():
            yield name, path, None


@pytest.mark.parametrize("name", [m[0] for m in closed_meshes()])
def test_no_ray_through_a_shared_edge_or_vertex_escapes(name):
    """Every ray from outside that leaves a closed mesh crosses it an even number of times, rays
    aimed exactly at vertices and at edge midpoints included."""
    entry = next(m for m in closed_meshes() if m[0] == name)
    if entry[2] is None:
        v, f = read_mesh(entry[1])  # the file's own faces, shared vertices and all
    else:
        v, f = entry[1], entry[2]
    if not is_closed(f):
        pytest.skip(f"{name} is not a closed mesh")
    scene = raylab.Mesh(v, f).build("bvh")
    rng = np.random.default_rng(6)
    lo, hi = v.min(axis=0), v.max(axis=0)
    size = float(np.linalg.norm(hi - lo))
    centre = (lo + hi) / 2
    targets = [v[rng.choice(len(v), 3000)]]
    edges = f[rng.choice(len(f), 3000)]
    targets.append(((v[edges[:, 0]].astype(np.float64) + v[edges[:, 1]]) / 2).astype(np.float32))
    targets = np.concatenate(targets)
    o = rng.normal(size=targets.shape)
    o = (centre + o / np.linalg.norm(o, axis=1, keepdims=True) * size * 2).astype(np.float32)
    counts = scene.count_intersections(o, targets - o)
    assert (counts > 0).mean() > 0.9
    odd = np.flatnonzero(counts % 2)
    assert len(odd) == 0, f"{len(odd)} rays crossed an odd number of times, e.g. ray {odd[:5]}"
    # The brute-force structure counts the same.
    np.testing.assert_array_equal(raylab.Mesh(v, f).build("brute").count_intersections(o[:500], (targets - o)[:500]),
                                  counts[:500])


def read_mesh(path):
    """The vertices and faces of an OFF or OBJ file (the shared meshes' formats), for closedness."""
    text = open(path, encoding="ascii", errors="replace").read().split("\n")
    if str(path).endswith(".off"):
        words = " ".join(line.split("#")[0] for line in text).split()
        nv, nf = int(words[1]), int(words[2])
        v = np.array(words[4:4 + 3 * nv], dtype=np.float32).reshape(nv, 3)
        rest = np.array(words[4 + 3 * nv:], dtype=np.int64)
        f = rest.reshape(nf, 4)[:, 1:]
        return v, f.astype(np.uint32)
    if str(path).endswith(".obj"):
        v = [line.split()[1:4] for line in text if line.startswith("v ")]
        f = [[int(w.split("/")[0]) - 1 for w in line.split()[1:4]] for line in text if line.startswith("f ")]
        return np.array(v, dtype=np.float32), np.array(f, dtype=np.uint32)
    pytest.skip(f"no reader here for {path}")


def test_contains_agrees_with_the_ball(sphere):
    v, f = icosphere(3)
    scene = raylab.Mesh(v, f)
    rng = np.random.default_rng(7)
    p = rng.uniform(-1.4, 1.4, size=(20000, 3)).astype(np.float32)
    r = np.linalg.norm(p, axis=1)
    keep = (r < 0.97) | (r > 1.01)  # the level-3 icosphere lies between radius 0.98 and 1
    inside = scene.contains(p[keep])
    assert inside.dtype == np.bool_
    np.testing.assert_array_equal(inside, r[keep] < 0.97)
    assert scene.contains(p[keep].reshape(-1, 1, 3)).shape == (keep.sum(), 1)


def test_per_ray_limits_and_chosen_fields(sphere):
    scene = raylab.Mesh(*sphere)
    o = np.array([[0.013, 0.021, 4]] * 3, np.float32)  # off the axis, where vertices lie
    d = np.array([[0, 0, -1]] * 3, np.float32)
    near = scene.intersect(o[:1], d[:1])["t"][0]
    # Per-ray limits: the whole ray, a ray stopping before the sphere, a ray starting inside it.
    tmax = np.array([np.inf, near, np.inf], np.float32)
    tmin = np.array([0, 0, near + 0.01], np.float64)  # converted to float32
    hits = scene.intersect(o, d, tmin=tmin, tmax=tmax, fields=["t", "prim_id"])
    assert set(hits) == {"t", "prim_id"}
    assert hits["t"][0] == near and hits["t"][1] == np.inf and 4.9 < hits["t"][2] < 5.01
    np.testing.assert_array_equal(scene.occluded(o, d, tmax=tmax), [True, False, True])
    np.testing.assert_array_equal(scene.count_intersections(o, d, tmin=tmin), [2, 2, 1])
    with pytest.raises(ValueError, match="tmax: an array of limits must have the rays' leading shape"):
        scene.intersect(o, d, tmax=tmax[:2])
    with pytest.raises(ValueError, match="fields: unknown answer 'depth'"):
        scene.intersect(o, d, fields=["depth"])
    with pytest.raises(TypeError, match="fields"):
        scene.intersect(o, d, fields="t")
