"""Rendering and the lab's figures from Python, against the command line's answers."""

import json
import subprocess

import numpy as np
import pytest

import raylab
from conftest import icosphere


def test_render_returns_the_linear_image_the_command_line_writes(tmp_path, binary):
    image = raylab.render("demo", width=48, height=32, spp=4, sampler="jittered", threads=2)
    assert image.shape == (32, 48, 3) and image.dtype == np.float32
    assert np.isfinite(image).all() and image.max() > 0.1
    exr = tmp_path / "cli.pfm"
    subprocess.run([binary, "render", "demo", "--width", "48", "--height", "32", "--spp", "4", "--sampler",
                    "jittered", "-o", str(exr)], check=True, capture_output=True)
    raylab.write_image(tmp_path / "py.pfm", image)
    # PFM stores float32 bottom row first; both files came from the same writer.
    assert (tmp_path / "py.pfm").read_bytes() == exr.read_bytes()


def test_render_does_not_depend_on_threads():
    one = raylab.render("demo", width=40, height=30, spp=4, threads=1)
    two = raylab.render("demo", width=40, height=30, spp=4, threads=2)
    np.testing.assert_array_equal(one, two)


def test_render_a_mesh_and_write_png(tmp_path):
    image = raylab.render(raylab.Mesh(*icosphere(2)), width=32, height=32)
    # The lit sphere in the middle, the background colour of a bare mesh in every corner.
    corners = image[[0, 0, -1, -1], [0, -1, 0, -1]]
    assert np.all(corners == corners[0]) and image[16, 16].sum() > 3 * corners[0].sum()
    raylab.write_image(tmp_path / "m.png", image)
    assert (tmp_path / "m.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_render_and_write_errors(tmp_path):
    with pytest.raises(ValueError, match="sampler"):
        raylab.render("demo", width=8, height=8, sampler="nonsense")
    with pytest.raises(ValueError, match="width"):
        raylab.render("demo", width=0, height=8)
    with pytest.raises(ValueError, match=r"image: expected shape \(\.\.\., 3\)"):
        raylab.write_image(tmp_path / "x.png", np.zeros((4, 4)))
    with pytest.raises(ValueError):
        raylab.write_image(tmp_path / "x.bmp", np.zeros((4, 4, 3), np.float32))
    assert not (tmp_path / "x.bmp").exists()


def test_compare_returns_the_command_lines_json(tmp_path, binary):
    result = raylab.compare("spd:balls?size=1", accels=["bvh", "grid"], width=32, height=32, repeat=1)
    out = tmp_path / "compare.json"
    subprocess.run([binary, "compare", "spd:balls?size=1", "--accels", "bvh,grid", "--width", "32", "--height", "32",
                    "--repeat", "1", "--json", str(out)], check=True, capture_output=True)
    cli = json.loads(out.read_text())
    assert set(cli) == set(result)
    names = [s["name"] for s in result["structures"]]
    assert names == [s["name"] for s in cli["structures"]] == ["bvh", "grid"]
    for ours, theirs in zip(result["structures"], cli["structures"]):
        assert ours["mismatches"] == theirs["mismatches"] == 0
        assert ours["rays"].keys() == theirs["rays"].keys()


def test_pinhole_rays_are_unit_and_centred():
    rays = raylab.pinhole_rays(5, 3, eye=(1, 2, 3), at=(1, 2, 0), fov=60)
    np.testing.assert_allclose(np.linalg.norm(rays[..., 3:], axis=-1), 1, rtol=1e-6)
    np.testing.assert_allclose(rays[1, 2, 3:], [0, 0, -1], atol=1e-6)
    assert np.all(rays[..., :3] == np.float32([1, 2, 3]))
    with pytest.raises(ValueError, match="fov"):
        raylab.pinhole_rays(4, 4, eye=(0, 0, 1), at=(0, 0, 0), fov=0)


def test_quality_returns_the_command_lines_json(tmp_path, binary):
    args = dict(samplers=["jittered", "adaptive"], budgets=[4], seeds=1, width=24, height=16)
    result = raylab.quality("aa-edges", reference_spp=64, **args)
    reference = raylab.render("aa-edges", width=24, height=16, spp=64, sampler="jittered")
    given = raylab.quality("aa-edges", reference=reference, **args)
    out = tmp_path / "quality.json"
    subprocess.run([binary, "quality", "aa-edges", "--samplers", "jittered,adaptive", "--budgets", "4", "--seeds",
                    "1", "--width", "24", "--height", "16", "--reference-spp", "64", "--json", str(out),
                    "--cache-dir", str(tmp_path)], check=True, capture_output=True)
    cli = json.loads(out.read_text())
    assert set(cli) == set(result)
    for key in ("rows",):
        ours = [(r["sampler"], r["budget"], r["rmse"]) for r in result[key]]
        theirs = [(r["sampler"], r["budget"], r["rmse"]) for r in cli[key]]
        assert ours == theirs
    assert len(given["rows"]) == 2
    with pytest.raises(ValueError, match="reference"):
        raylab.quality("aa-edges", reference=np.zeros((4, 4, 3), np.float32), **args)
