"""The instruction set of the kernels, chosen from Python: every usable set gives the same hits."""

import numpy as np
import pytest

import raylab


def test_every_usable_set_gives_the_same_hits():
    sets = raylab.usable_isas()
    assert raylab.isa() == sets[-1]
    mesh = raylab.Mesh(
        np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.2]], dtype=np.float32),
        np.array([[0, 1, 2], [1, 3, 2]], dtype=np.uint32),
    )
    rays = raylab.pinhole_rays(32, 24, eye=(0.4, 0.4, 2), at=(0.4, 0.4, 0), fov=40)
    results = {}
    try:
        for name in sets:
            raylab.set_isa(name)
            assert raylab.isa() == name
            results[name] = mesh.build("bvh").intersect(rays)
    finally:
        raylab.set_isa(sets[-1])
    first = results[sets[0]]
    assert np.count_nonzero(first["prim_id"] >= 0) > 100
    for name, hits in results.items():
        for key in ("t", "prim_id", "uv", "normal"):
            np.testing.assert_array_equal(hits[key], first[key], err_msg=f"{name}: {key}")


def test_unknown_set_is_a_value_error_naming_the_argument():
    with pytest.raises(ValueError, match="isa: 'sse9'"):
        raylab.set_isa("sse9")
