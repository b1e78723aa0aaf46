"""The path integrator and the environment light from Python, against the command line's answers."""

import subprocess

import numpy as np
import pytest

import raylab


def test_path_render_is_the_command_lines_image(tmp_path, binary):
    image = raylab.render("cornell", width=24, height=24, spp=4, integrator="path", max_depth=4, threads=2)
    assert image.shape == (24, 24, 3) and np.isfinite(image).all()
    cli = tmp_path / "cli.pfm"
    subprocess.run([binary, "render", "cornell", "--width", "24", "--height", "24", "--spp", "4", "--integrator",
                    "path", "--max-depth", "4", "-o", str(cli)], check=True, capture_output=True)
    np.testing.assert_array_equal(raylab.read_image(cli), image)


def test_path_differs_from_whitted_and_lights_the_ceiling():
    # Whitted lights the box's ceiling only by its ambient term; the path integrator by the light
    # the floor and walls send up.
    whitted = raylab.render("cornell", width=32, height=32, spp=16, integrator="whitted")
    path = raylab.render("cornell", width=32, height=32, spp=16, integrator="path")
    assert not np.array_equal(whitted, path)
    ceiling = path[1:3, 4:10].mean()
    assert ceiling > 0.02


def test_environment_lights_a_mesh_scene(tmp_path):
    dark = raylab.render("demo", width=24, height=16, spp=4, integrator="path", env="0,0,0")
    lit = raylab.render("demo", width=24, height=16, spp=4, integrator="path", env="1,1,1")
    assert lit.mean() > dark.mean() + 0.1
    sky = tmp_path / "sky.pfm"
    raylab.write_image(sky, np.ones((8, 16, 3), dtype=np.float32))
    from_file = raylab.render("demo", width=24, height=16, spp=4, integrator="path", env=sky, env_rotate=30.0)
    assert from_file.shape == (16, 24, 3) and np.isfinite(from_file).all()


def test_bad_integrator_and_environment_name_the_argument(tmp_path):
    with pytest.raises(ValueError, match="integrator: .*whitted, path"):
        raylab.render("demo", width=8, height=8, integrator="photon")
    with pytest.raises(ValueError, match="max_depth"):
        raylab.render("demo", width=8, height=8, max_depth=0)
    with pytest.raises(ValueError, match="env: "):
        raylab.render("demo", width=8, height=8, integrator="path", env=str(tmp_path / "missing.exr"))


def test_read_image_round_trips_what_write_image_wrote(tmp_path):
    image = np.random.default_rng(3).random((5, 7, 3), dtype=np.float32)
    raylab.write_image(tmp_path / "x.exr", image)
    np.testing.assert_array_equal(raylab.read_image(tmp_path / "x.exr"), image)
    with pytest.raises(Exception, match="missing"):
        raylab.read_image(tmp_path / "missing.pfm")
