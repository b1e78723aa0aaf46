"""Arrays in place: no conversion copy of float32 / uint32 inputs, the GIL released while tracing,
Ctrl-C answered."""

import _thread
import gc
import threading
import time
import tracemalloc

import numpy as np
import pytest

import raylab
from conftest import icosphere


def test_mesh_keeps_the_given_arrays(sphere):
    v, f = sphere
    scene = raylab.Mesh(v, f)
    assert scene.vertices is v and scene.triangles is f


def peak_bytes_of(call):
    """Peak of numpy's allocations (numpy reports them to tracemalloc) during `call`."""
    tracemalloc.start()
    try:
        result = call()
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    return peak, result


def test_float32_rays_are_read_without_a_copy(sphere):
    scene = raylab.Mesh(*sphere).build()
    n = 400000
    rays = np.random.default_rng(1).normal(size=(n, 6)).astype(np.float32)
    # Answers: t, prim_id, object_id (4 bytes each), uv (8) and normal (12). Each is 1 MiB or
    # more here, so it lies in one of raylab's large blocks (huge pages), which tracemalloc does
    # not see: what numpy allocates is only what the call copies. A copy of the rays would be 24
    # bytes per ray.
    answers = scene.intersect(rays)
    assert all(a.nbytes >= 2**20 for a in answers.values())
    peak, _ = peak_bytes_of(lambda: scene.intersect(rays))
    assert peak < 2**20, peak
    # Column slices of one array are read in place too.
    peak, _ = peak_bytes_of(lambda: scene.intersect(rays[:, :3], rays[:, 3:]))
    assert peak < 2**20, peak
    # The test can see a copy: float64 rays are converted.
    rays64 = rays.astype(np.float64)
    peak, _ = peak_bytes_of(lambda: scene.intersect(rays64))
    assert peak >= 24 * n
    peak, _ = peak_bytes_of(lambda: scene.occluded(rays))
    assert peak < n + 2**20


def test_float32_uint32_mesh_is_read_without_a_copy():
    v, f = icosphere(5)
    assert v.dtype == np.float32 and f.dtype == np.uint32
    peak, _ = peak_bytes_of(lambda: raylab.Mesh(v, f))
    assert peak < 2**16, peak  # the scene's own triangles live outside numpy
    peak, _ = peak_bytes_of(lambda: raylab.Mesh(v, f.astype(np.int64)))
    assert peak >= f.size * 4


def test_the_gil_is_released_while_rays_are_traced(sphere):
    scene = raylab.Mesh(*icosphere(4)).build()
    rays = np.random.default_rng(2).normal(size=(3_000_000, 6)).astype(np.float32)
    ticks = []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    thread = threading.Thread(target=ticker)
    thread.start()
    start = time.perf_counter()
    scene.intersect(rays, threads=1)
    end = time.perf_counter()
    stop.set()
    thread.join()
    during = [t for t in ticks if start < t < end]
    # A held GIL would let the ticker run only at the switch interval's end, if at all.
    assert len(during) > 10, (len(during), end - start)


def test_ctrl_c_interrupts_a_long_call():
    scene = raylab.Mesh(*icosphere(4)).build()
    rays = np.random.default_rng(3).normal(size=(10_000_000, 6)).astype(np.float32)
    timer = threading.Timer(0.3, _thread.interrupt_main)
    start = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        scene.count_intersections(rays, threads=1)
    elapsed = time.perf_counter() - start
    timer.cancel()
    assert elapsed < 0.3 + 0.5, elapsed


def test_large_answers_are_arrays_of_their_own_that_outlive_the_scene(sphere):
    scene = raylab.Mesh(*sphere).build()
    n = 300000  # t alone is 1.2 MB: every answer lies in a large block
    rays = np.random.default_rng(2).normal(size=(n, 6)).astype(np.float32)
    first, second = scene.intersect(rays), scene.intersect(rays)
    for name in first:
        assert first[name].nbytes >= 2**20
        assert not np.shares_memory(first[name], second[name]), name
        np.testing.assert_array_equal(first[name], second[name])
    assert np.isfinite(first["t"]).any() and np.isinf(first["t"]).any()
    first["t"][:] = -1.0  # writable, and only its own
    assert not (second["t"] == -1.0).any()
    del scene
    gc.collect()
    assert (first["t"] == -1.0).all()
    assert second["prim_id"].dtype == np.int32 and second["prim_id"].shape == (n,)
